// towdb audit: how far a database's answers can be trusted between its stored
// cases. N random questions inside the database's own span are answered from
// the database (the query library, no extrapolation) and by direct simulation
// (the chain of `towdb simulate`), and the errors are summarised.
//
// The compared quantity is the dynamic tension exceeded with probability
// 0.001 in one day (the database's planning value, results.dynamic_999_kips)
// and the extreme tension = mean + that dynamic tension. Relative error =
// |answer - simulation| / simulation. The printed uncertainty "covers" a
// question when |answer - simulation| <= uncertainty_kips of the answer.
//
// Draws (deterministic for a seed, independent of threads): question i uses
// RandomStream(seed, i): a stored (tug, tow, line) group uniformly, then
// speed, wind, heading (folded to [0, 180]) and towline length uniformly in
// that group's stored span (finished Pierson-Moskowitz cases), rounded to
// 0.01 kt, 0.01 kt, 0.1 deg and 1 ft so that the printed question can be
// asked again; then the simulation's seed. Mean tension: the calculated
// default of `towdb query` (database_basis.hpp) when the database records its
// basis, else uniform in the group's stored mean-tension span.
#ifndef TOWDB_CLI_AUDIT_HPP
#define TOWDB_CLI_AUDIT_HPP

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "database_basis.hpp"
#include "io/ship_file.hpp"

namespace towdb::cli {

// The stored span of one (tug, tow, line) group.
struct GroupSpan {
  std::string tug, tow, line;
  double speed_lo_kt = 0, speed_hi_kt = 0;
  double wind_lo_kt = 0, wind_hi_kt = 0;
  double heading_lo_deg = 0, heading_hi_deg = 0;  // folded to [0, 180]
  double length_lo_ft = 0, length_hi_ft = 0;
  double mean_lo_lbf = 0, mean_hi_lbf = 0;
};

struct DatabaseSpan {
  std::vector<GroupSpan> groups;  // ordered by tug, tow, line
  int days = 0;                   // days of most finished cases (ties: the larger)
};

// Reads the spans; throws InputError when the database has no finished
// Pierson-Moskowitz (wind) case to draw from.
DatabaseSpan read_database_span(const std::filesystem::path& db_path);

struct AuditQuestion {
  int index = 0;
  std::string tug, tow, line;
  double speed_kt = 0, wind_kt = 0, heading_deg = 0, length_ft = 0, mean_tension_lbf = 0;
  std::uint64_t seed = 0;  // of the direct simulation
};

struct AuditOutcome {
  AuditQuestion q;
  // From the database without extrapolation.
  bool answered = false;
  std::string refusal;  // the query library's message when not answered
  double answer_999_kips = 0, uncertainty_kips = 0, answer_extreme_lbf = 0;
  // With extrapolation, for reference (NaN when even that is refused).
  double extrapolated_999_kips = 0;
  // Direct simulation (NaN when it failed: simulation_error says why).
  bool simulated = false;
  std::string simulation_error;
  double simulated_999_kips = 0, simulated_ci_low_kips = 0, simulated_ci_high_kips = 0, simulated_extreme_lbf = 0;
  // Errors (NaN when not answered or not simulated).
  double rel_error_999 = 0, rel_error_extreme = 0, rel_error_extrapolated_999 = 0;
  bool covered = false;
};

struct ErrorStats {
  int samples = 0;
  double median = 0, p90 = 0, max = 0;  // NaN without samples
  int worst_index = -1;                 // question with the largest error
};

struct AuditSummary {
  int draws = 0, answered = 0, not_answered = 0, simulation_failed = 0;
  ErrorStats dynamic_999, extreme, extrapolated_999;
  int covered = 0;
  double coverage = 0;  // covered / (answered and simulated); NaN without any
};

struct AuditOptions {
  int draws = 0;
  std::uint64_t seed = 1;
  int days = 0;     // of each simulation
  int threads = 0;  // parallel_for threads over the questions
};

std::vector<AuditQuestion> draw_questions(const DatabaseSpan& span, const std::optional<DatabaseBasis>& basis,
                                          const io::ShipCatalog& catalog, const std::filesystem::path& db_path,
                                          const AuditOptions& options);

// Answers every question from the database and simulates it (in parallel;
// results do not depend on the thread count).
std::vector<AuditOutcome> run_audit(const std::filesystem::path& db_path, const io::ShipCatalog& catalog,
                                    const std::vector<AuditQuestion>& questions, const AuditOptions& options);

// Replay: the questions of an earlier audit answered again from the database
// as it is now (after a change to the query library or to the stored cases),
// against that audit's own simulations, which `earlier` carries; nothing is
// simulated. Answers and errors are recomputed, the simulations kept.
void replay_audit(const std::filesystem::path& db_path, std::vector<AuditOutcome>* earlier);

AuditSummary summarise(const std::vector<AuditOutcome>& outcomes);

// Linear interpolation between order statistics at fraction f of the way
// from the smallest (0) to the largest (1); NaN for an empty list.
double quantile(std::vector<double> values, double f);

}  // namespace towdb::cli

#endif  // TOWDB_CLI_AUDIT_HPP
