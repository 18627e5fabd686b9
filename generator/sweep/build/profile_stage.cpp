#include "sweep/build/profile_stage.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

#include "common/error.hpp"
#include "common/parallel_for.hpp"
#include "common/units.hpp"
#include "io/ship_file.hpp"
#include "store/key_bytes.hpp"

namespace towdb::sweep {

FinishedCases::FinishedCases(store::Database& db)
    : by_key_(db.prepare("SELECT case_id, status FROM cases WHERE case_key = ?")) {}

std::int64_t FinishedCases::case_id(const CaseKeys& keys) {
  by_key_.reset();
  by_key_.bind_blob(1, store::key_bytes(keys.case_key, "case_key"));
  return by_key_.step() && by_key_.column_text(1) == "done" ? by_key_.column_int(0) : 0;
}

std::string line_profile_key(std::string head, std::vector<std::string> case_keys) {
  std::sort(case_keys.begin(), case_keys.end());
  for (const auto& k : case_keys) head += "|" + k;
  return store::key_bytes(io::sha256_hex(head), "profile_key");
}

std::vector<double> checked_sigma_kips(const std::vector<double>& sigma_n) {
  std::vector<double> kips;
  kips.reserve(sigma_n.size());
  for (double n : sigma_n) {
    const double s = units::n_to_kips(n);
    if (!(s > 0.0 && std::isfinite(s))) {
      throw NumericalError("linear dynamic-tension sigma " + format_value(s) + " kips; allowed: finite, > 0");
    }
    kips.push_back(s);
  }
  return kips;
}

void point_cases_at(store::Database& db, const char* column, const std::vector<std::int64_t>& case_ids,
                    std::int64_t profile_id) {
  const std::string c(column);
  store::Statement st = db.prepare("UPDATE cases SET " + c + " = ? WHERE case_id = ? AND " + c + " IS NOT ?");
  for (std::int64_t id : case_ids) {
    st.reset();
    if (profile_id == 0) {
      st.bind_null(1).bind(2, id).bind_null(3);
    } else {
      st.bind(1, profile_id).bind(2, id).bind(3, profile_id);
    }
    st.run();
  }
}

void run_stage_chunks(store::Database& db, const StageWork& work, int threads, const std::atomic<bool>* stop,
                      ProfileSummary& summary) {
  constexpr std::size_t kChunk = 32;
  for (std::size_t begin = 0; begin < work.count; begin += kChunk) {
    if (stop && stop->load()) {
      summary.interrupted = true;
      break;
    }
    const std::size_t end = std::min(work.count, begin + kChunk);
    std::vector<std::string> blob(end - begin), failure(end - begin);
    parallel_for(static_cast<std::int64_t>(begin), static_cast<std::int64_t>(end), threads, [&](std::int64_t w) {
      const auto k = static_cast<std::size_t>(w) - begin;
      try {
        blob[k] = work.compute(static_cast<std::size_t>(w));
      } catch (const std::exception& e) {
        failure[k] = *e.what() ? e.what() : "unknown error";
      }
    });
    for (std::size_t w = begin; w < end; ++w) {
      const std::size_t k = w - begin;
      if (!failure[k].empty()) {
        ++summary.failed;
        summary.failures.push_back(work.name(w) + ": " + failure[k]);
        db.transaction([&] { work.clear(w); });
        continue;
      }
      db.transaction([&] { work.write(w, blob[k]); });
      ++summary.computed;
    }
  }
  std::sort(summary.failures.begin(), summary.failures.end());
}

}  // namespace towdb::sweep
