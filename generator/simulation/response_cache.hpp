// The process-wide memo of strip-theory responses (seakeeping/): a sweep
// shares them between all cases with the same vessel file, speed, heading,
// frequency grid and response options (wind, towline and mean tension do not
// enter). Concurrent requests for one key wait for a single computation; a
// computation that throws is rethrown to every waiter.
#ifndef TOWDB_SIMULATION_RESPONSE_CACHE_HPP
#define TOWDB_SIMULATION_RESPONSE_CACHE_HPP

#include <memory>
#include <vector>

#include "model/vessel.hpp"
#include "seakeeping/seakeeping.hpp"

namespace towdb::simulation {

// Strip-theory responses of a vessel through the process-wide memo that
// run_case uses (so callers such as the sweep's mean-tension calculator
// share the work with the cases).
std::shared_ptr<const std::vector<seakeeping::VesselResponse>> cached_responses(
    const model::Vessel& vessel, double speed_m_s, double heading_rad, const std::vector<double>& omegas_rad_s,
    const seakeeping::ResponseOptions& options);

}  // namespace towdb::simulation

#endif  // TOWDB_SIMULATION_RESPONSE_CACHE_HPP
