#include "simulation/response_cache.hpp"

#include <bit>
#include <cstdint>
#include <future>
#include <map>
#include <mutex>
#include <string>

namespace towdb::simulation {

namespace {

// Process-wide memo of strip-theory responses: a sweep shares them between
// all cases with the same vessel, speed, heading and grid (wind, towline and
// mean tension do not enter). Concurrent requests wait for one computation.
class ResponseCache {
 public:
  using Responses = std::vector<seakeeping::VesselResponse>;
  std::shared_ptr<const Responses> get(const model::Vessel& vessel, double speed_m_s, double heading_rad,
                                       const std::vector<double>& omegas, const seakeeping::ResponseOptions& o) {
    std::string key = vessel.name + "|" + vessel.content_sha256;
    auto add = [&key](double x) { key += "|" + std::to_string(std::bit_cast<std::uint64_t>(x)); };
    add(speed_m_s);
    add(heading_rad);
    for (double w : omegas) add(w);
    add(o.min_encounter_frequency_nondim);
    key += o.transom_terms ? "|t" : "|n";
    key += o.added_resistance_aft_of_beam ? "|a" : "|z";
    key += o.surge_diffraction ? "|d" : "|f";
    std::promise<std::shared_ptr<const Responses>> promise;
    std::shared_future<std::shared_ptr<const Responses>> future;
    bool compute = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = entries_.find(key);
      if (it == entries_.end()) {
        future = promise.get_future().share();
        entries_.emplace(key, future);
        compute = true;
      } else {
        future = it->second;
      }
    }
    if (compute) {
      try {
        promise.set_value(std::make_shared<const Responses>(
            seakeeping::compute_response(vessel, speed_m_s, heading_rad, omegas, o)));
      } catch (...) {
        promise.set_exception(std::current_exception());
      }
    }
    return future.get();
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::shared_future<std::shared_ptr<const Responses>>> entries_;
};

ResponseCache& response_cache() {
  static ResponseCache cache;
  return cache;
}

}  // namespace

std::shared_ptr<const std::vector<seakeeping::VesselResponse>> cached_responses(
    const model::Vessel& vessel, double speed_m_s, double heading_rad, const std::vector<double>& omegas_rad_s,
    const seakeeping::ResponseOptions& options) {
  return response_cache().get(vessel, speed_m_s, heading_rad, omegas_rad_s, options);
}

}  // namespace towdb::simulation
