// What the heading-profile (EQ-SWEEP-8) and speed-profile (EQ-SWEEP-9) stages
// share: pointing a line's cases at their profile row, and computing the
// lines to do a chunk at a time in parallel while writing them in order (so
// the rows do not depend on the thread count, and a killed build keeps every
// chunk written before).
#ifndef TOWDB_SWEEP_PROFILE_STAGE_HPP
#define TOWDB_SWEEP_PROFILE_STAGE_HPP

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "store/database.hpp"
#include "sweep/build/profiles.hpp"
#include "sweep/spec/keys.hpp"

namespace towdb::sweep {

// The case_id of each finished ("done") case of the sweep, by its keys; 0 for
// a case not stored or not finished.
class FinishedCases {
 public:
  explicit FinishedCases(store::Database& db);
  std::int64_t case_id(const CaseKeys& keys);

 private:
  store::Statement by_key_;
};

// profile_key of a line: SHA-256 of `head` followed by "|" and each of the
// line's case keys in sorted order (32 bytes).
std::string line_profile_key(std::string head, std::vector<std::string> case_keys);

// A profile function's values [N] as kips, each checked finite and > 0
// (NumericalError naming the value otherwise).
std::vector<double> checked_sigma_kips(const std::vector<double>& sigma_n);

// Sets `column` (profile_id or speed_profile_id) of the cases to
// `profile_id` (NULL for 0), touching only rows that change.
void point_cases_at(store::Database& db, const char* column, const std::vector<std::int64_t>& case_ids,
                    std::int64_t profile_id);

// One stage's work: `count` lines, computed by `compute(i)` (the row's packed
// values; throws on failure) in parallel chunks, each stored by `write(i,
// blob)` in its own transaction in line order. A failure is counted in
// `summary` with `name(i)` and `clear(i)` runs in a transaction instead. A
// stop request between chunks sets summary.interrupted.
struct StageWork {
  std::size_t count = 0;
  std::function<std::string(std::size_t)> compute;
  std::function<void(std::size_t, const std::string&)> write;
  std::function<void(std::size_t)> clear;
  std::function<std::string(std::size_t)> name;
};
void run_stage_chunks(store::Database& db, const StageWork& work, int threads, const std::atomic<bool>* stop,
                      ProfileSummary& summary);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_PROFILE_STAGE_HPP
