// `towdb status`: a summary of a towdb database (read-only).
#ifndef TOWDB_SWEEP_STATUS_HPP
#define TOWDB_SWEEP_STATUS_HPP

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace towdb::sweep {

struct BuildRecord {
  std::int64_t build_id = 0;
  std::string code_version;
  std::string sweep_file;
  std::string host;
  int threads = 0;
  int mpi_ranks = 0;
  std::string started_utc;
  std::string finished_utc;  // empty while running
  std::string status;
  int cases_done = 0;
  int cases_failed = 0;
};

struct FailedCase {
  std::int64_t case_id = 0;
  std::string sweep_label;
  std::string tug;
  std::string tow;
  std::string error_message;
};

struct StatusReport {
  int schema_version = 0;
  std::int64_t cases = 0;
  std::map<std::string, std::int64_t> cases_by_status;  // pending, running, done, failed
  std::map<std::string, std::int64_t> cases_by_sweep_label;
  std::int64_t results = 0;
  std::int64_t daily_maxima = 0;
  std::int64_t towline_fits = 0;
  std::int64_t heading_profiles = 0;   // heading_profiles rows (EQ-SWEEP-8)
  std::int64_t cases_with_profile = 0;  // cases whose profile_id is set
  std::int64_t speed_profiles = 0;      // speed_profiles rows (EQ-SWEEP-9)
  std::int64_t cases_with_speed_profile = 0;  // cases whose speed_profile_id is set
  std::int64_t vessels = 0;
  std::optional<double> total_runtime_s;  // sum of results.runtime_s
  std::vector<BuildRecord> builds;        // newest first, at most `max_builds`
  std::vector<FailedCase> failed;         // at most `max_failed`, by case_id
  std::optional<std::string> last_audit;   // meta.last_audit: the JSON summary `towdb audit` stored
  // The newest build that computed a stored case or profile (none when nothing is computed):
  // what an audit names as the content it measured. A build that computes nothing (every case
  // up to date) does not change it.
  std::optional<std::int64_t> content_build_id;
};

StatusReport read_status(const std::filesystem::path& db_path, int max_builds = 10, int max_failed = 20);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_STATUS_HPP
