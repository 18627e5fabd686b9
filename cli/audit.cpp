#include "audit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.hpp"
#include "common/parallel_for.hpp"
#include "common/random.hpp"
#include "common/units.hpp"
#include "query_database.hpp"
#include "store/database.hpp"
#include "sweep/build/simulation_runner.hpp"
#include "towdb/query.hpp"

namespace towdb::cli {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Rounding of the drawn values (so that a printed question can be asked again).
constexpr double kSpeedStep_kt = 0.01;
constexpr double kWindStep_kt = 0.01;
constexpr double kHeadingStep_deg = 0.1;
constexpr double kLengthStep_ft = 1.0;
constexpr double kMeanStep_lbf = 1.0;

// Uniform in [lo, hi], rounded to `step` and kept inside [lo, hi].
double draw_in(RandomStream& rng, double lo, double hi, double step) {
  const double x = std::round((lo + rng.uniform01() * (hi - lo)) / step) * step;
  return std::clamp(x, lo, hi);
}

int most_common_days(store::Database& db) {
  store::Statement st = db.prepare(
      "SELECT days FROM cases WHERE status = 'done' GROUP BY days ORDER BY count(*) DESC, days DESC LIMIT 1");
  return st.step() ? static_cast<int>(st.column_int(0)) : 0;
}

}  // namespace

DatabaseSpan read_database_span(const std::filesystem::path& db_path) {
  store::Database db = store::Database::open(db_path, store::Database::Mode::kReadOnly);
  DatabaseSpan span;
  store::Statement st = db.prepare(
      "SELECT c.tug_name, c.tow_name, c.line_type, min(c.speed_kt), max(c.speed_kt), min(c.wind_kt), "
      "max(c.wind_kt), min(CASE WHEN c.heading_deg > 180 THEN 360 - c.heading_deg ELSE c.heading_deg END), "
      "max(CASE WHEN c.heading_deg > 180 THEN 360 - c.heading_deg ELSE c.heading_deg END), min(c.length_ft), "
      "max(c.length_ft), min(c.mean_tension_lbf), max(c.mean_tension_lbf) "
      "FROM cases c JOIN results r ON r.case_id = c.case_id "
      "WHERE c.status = 'done' AND c.spectrum = 'pierson-moskowitz' AND c.wind_kt IS NOT NULL "
      "GROUP BY c.tug_name, c.tow_name, c.line_type ORDER BY c.tug_name, c.tow_name, c.line_type");
  while (st.step()) {
    GroupSpan g;
    g.tug = st.column_text(0);
    g.tow = st.column_text(1);
    g.line = st.column_text(2);
    g.speed_lo_kt = st.column_double(3);
    g.speed_hi_kt = st.column_double(4);
    g.wind_lo_kt = st.column_double(5);
    g.wind_hi_kt = st.column_double(6);
    g.heading_lo_deg = st.column_double(7);
    g.heading_hi_deg = st.column_double(8);
    g.length_lo_ft = st.column_double(9);
    g.length_hi_ft = st.column_double(10);
    g.mean_lo_lbf = st.column_double(11);
    g.mean_hi_lbf = st.column_double(12);
    span.groups.push_back(g);
  }
  if (span.groups.empty()) {
    throw InputError("--db " + db_path.string() +
                     ": no finished case in a wind (Pierson-Moskowitz) sea; the audit draws its questions from those");
  }
  span.days = most_common_days(db);
  return span;
}

std::vector<AuditQuestion> draw_questions(const DatabaseSpan& span, const std::optional<DatabaseBasis>& basis,
                                          const io::ShipCatalog& catalog, const std::filesystem::path& db_path,
                                          const AuditOptions& options) {
  std::vector<AuditQuestion> out;
  const auto groups = static_cast<double>(span.groups.size());
  for (int i = 0; i < options.draws; ++i) {
    RandomStream rng(options.seed, static_cast<std::uint64_t>(i));
    const auto k = std::min(span.groups.size() - 1, static_cast<std::size_t>(rng.uniform01() * groups));
    const GroupSpan& g = span.groups[k];
    AuditQuestion q;
    q.index = i;
    q.tug = g.tug;
    q.tow = g.tow;
    q.line = g.line;
    q.speed_kt = draw_in(rng, g.speed_lo_kt, g.speed_hi_kt, kSpeedStep_kt);
    q.wind_kt = draw_in(rng, g.wind_lo_kt, g.wind_hi_kt, kWindStep_kt);
    q.heading_deg = draw_in(rng, g.heading_lo_deg, g.heading_hi_deg, kHeadingStep_deg);
    q.length_ft = draw_in(rng, g.length_lo_ft, g.length_hi_ft, kLengthStep_ft);
    const double mean_u = rng.uniform01();  // drawn in both cases: the stream stays the same
    q.mean_tension_lbf =
        std::round((g.mean_lo_lbf + mean_u * (g.mean_hi_lbf - g.mean_lo_lbf)) / kMeanStep_lbf) * kMeanStep_lbf;
    q.seed = rng.next_u64() >> 1;  // below 2^63: fits the schema's INTEGER seeds too
    out.push_back(q);
  }
  if (!basis) return out;
  // The calculated mean tension (strip theory: seconds per question), in
  // parallel; each index writes only its own question.
  parallel_for(0, static_cast<std::int64_t>(out.size()), options.threads, [&](std::int64_t i) {
    AuditQuestion& q = out[static_cast<std::size_t>(i)];
    q.mean_tension_lbf =
        calculated_mean_tension(*basis, catalog, db_path, q.tow, q.speed_kt, q.wind_kt, q.heading_deg).total_lbf;
  });
  return out;
}

namespace {

query::QueryRequest request_of(const AuditQuestion& q, bool extrapolate) {
  query::QueryRequest r;
  r.tug = q.tug;
  r.tow = q.tow;
  r.line = q.line;
  r.values.speed_kt = q.speed_kt;
  r.values.wind_kt = q.wind_kt;
  r.values.heading_deg = q.heading_deg;
  r.values.length_ft = q.length_ft;
  r.values.mean_tension_lbf = q.mean_tension_lbf;
  r.values.probability = 0.001;  // the database's planning value
  r.values.tow_days = 1.0;
  r.values.extrapolate = extrapolate ? 1 : 0;
  return r;
}

// The database's answers (serial: a query handle is single-threaded and a
// query takes microseconds), every answer field set whatever it held before
// (a replay's outcomes carry an earlier database's). Errors other than the
// caller's are the audit's.
void answer_from_database(const std::filesystem::path& db_path, std::vector<AuditOutcome>* outcomes) {
  const std::unique_ptr<query::Database> opened = open_query_database("--db", db_path.string());
  query::Database& db = *opened;
  for (AuditOutcome& o : *outcomes) {
    o.answered = false;
    o.refusal.clear();
    o.answer_999_kips = o.uncertainty_kips = o.answer_extreme_lbf = o.extrapolated_999_kips = kNaN;
    if (!(o.q.mean_tension_lbf > 0.0)) {
      o.refusal = "calculated mean tension " + format_value(o.q.mean_tension_lbf) +
                  " lbf is not positive (wind and sea push the tow)";
      continue;
    }
    try {
      const query::QueryResult r = db.query(request_of(o.q, false));
      o.answered = true;
      o.answer_999_kips = r.values.dynamic_999_kips;
      o.uncertainty_kips = r.values.uncertainty_kips;
      o.answer_extreme_lbf = r.values.extreme_tension_lbf;
    } catch (const query::QueryError& e) {
      if (!e.is_input()) throw;
      o.refusal = e.what();
    }
    try {
      o.extrapolated_999_kips = db.query(request_of(o.q, true)).values.dynamic_999_kips;
    } catch (const query::QueryError& e) {
      if (!e.is_input()) throw;
    }
  }
}

// One direct simulation, as `towdb simulate` runs it with the build's options.
void simulate(const io::ShipCatalog& catalog, int days, AuditOutcome* o) {
  const AuditQuestion& q = o->q;
  const model::Vessel& tug = catalog.vessel(q.tug).vessel;
  const model::Vessel& tow = catalog.vessel(q.tow).vessel;
  simulation::CaseInputs in;
  in.tug = &tug;
  in.tow = &tow;
  const model::LineKind kind = q.line == "fiber" ? model::LineKind::kFiber : model::LineKind::kWire;
  in.towline = catalog.towline(tug, kind, units::ft_to_m(q.length_ft));
  in.speed_m_s = units::kt_to_m_s(q.speed_kt);
  sweep::SeaSpec sea;
  sea.wind_kt = q.wind_kt;
  in.sea = sweep::sea_state(sea, q.heading_deg);
  in.mean_tension_n = units::lbf_to_n(q.mean_tension_lbf);
  in.days = days;
  in.seed = q.seed;
  const simulation::CaseResult r = simulation::run_case(in, build_case_options());
  o->simulated = true;
  o->simulated_999_kips = units::n_to_kips(r.statistics.dynamic_999_n);
  o->simulated_ci_low_kips = units::n_to_kips(r.statistics.ci_low_n);
  o->simulated_ci_high_kips = units::n_to_kips(r.statistics.ci_high_n);
  o->simulated_extreme_lbf = q.mean_tension_lbf + units::n_to_lbf(r.statistics.dynamic_999_n);
}

void compute_errors(AuditOutcome* o) {
  o->rel_error_999 = o->rel_error_extreme = o->rel_error_extrapolated_999 = kNaN;
  o->covered = false;
  if (!o->simulated) return;
  const double sim = o->simulated_999_kips;
  if (std::isfinite(o->extrapolated_999_kips))
    o->rel_error_extrapolated_999 = std::abs(o->extrapolated_999_kips - sim) / sim;
  if (!o->answered) return;
  o->rel_error_999 = std::abs(o->answer_999_kips - sim) / sim;
  o->rel_error_extreme = std::abs(o->answer_extreme_lbf - o->simulated_extreme_lbf) / o->simulated_extreme_lbf;
  o->covered = std::abs(o->answer_999_kips - sim) <= o->uncertainty_kips;
}

ErrorStats stats_of(const std::vector<AuditOutcome>& outcomes, double AuditOutcome::*field) {
  ErrorStats s;
  std::vector<double> v;
  double worst = -1.0;
  for (const AuditOutcome& o : outcomes) {
    const double e = o.*field;
    if (!std::isfinite(e)) continue;
    v.push_back(e);
    if (e > worst) {
      worst = e;
      s.worst_index = o.q.index;
    }
  }
  s.samples = static_cast<int>(v.size());
  s.median = quantile(v, 0.5);
  s.p90 = quantile(v, 0.9);
  s.max = v.empty() ? kNaN : worst;
  return s;
}

}  // namespace

double quantile(std::vector<double> values, double f) {
  if (values.empty()) return kNaN;
  std::sort(values.begin(), values.end());
  const double pos = f * static_cast<double>(values.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(pos));
  if (i + 1 >= values.size()) return values.back();
  return values[i] + (pos - static_cast<double>(i)) * (values[i + 1] - values[i]);
}

std::vector<AuditOutcome> run_audit(const std::filesystem::path& db_path, const io::ShipCatalog& catalog,
                                    const std::vector<AuditQuestion>& questions, const AuditOptions& options) {
  std::vector<AuditOutcome> out(questions.size());
  for (std::size_t i = 0; i < questions.size(); ++i) out[i].q = questions[i];
  answer_from_database(db_path, &out);
  // Every question with a positive mean tension is simulated, answered or not,
  // so that the extrapolated answers can be measured too. Each index writes
  // only its own outcome: bit-identical for any thread count.
  parallel_for(0, static_cast<std::int64_t>(out.size()), options.threads, [&](std::int64_t i) {
    AuditOutcome& o = out[static_cast<std::size_t>(i)];
    o.simulated_999_kips = o.simulated_extreme_lbf = kNaN;
    if (!(o.q.mean_tension_lbf > 0.0)) return;
    try {
      simulate(catalog, options.days, &o);
    } catch (const Error& e) {  // reported per question, never dropped
      o.simulated = false;
      o.simulation_error = e.what();
    }
  });
  for (AuditOutcome& o : out) compute_errors(&o);
  return out;
}

void replay_audit(const std::filesystem::path& db_path, std::vector<AuditOutcome>* earlier) {
  answer_from_database(db_path, earlier);
  for (AuditOutcome& o : *earlier) compute_errors(&o);
}

AuditSummary summarise(const std::vector<AuditOutcome>& outcomes) {
  AuditSummary s;
  s.draws = static_cast<int>(outcomes.size());
  int judged = 0;
  for (const AuditOutcome& o : outcomes) {
    s.answered += o.answered ? 1 : 0;
    s.not_answered += o.answered ? 0 : 1;
    s.simulation_failed += (o.q.mean_tension_lbf > 0.0 && !o.simulated) ? 1 : 0;
    if (o.answered && o.simulated) {
      ++judged;
      s.covered += o.covered ? 1 : 0;
    }
  }
  s.dynamic_999 = stats_of(outcomes, &AuditOutcome::rel_error_999);
  s.extreme = stats_of(outcomes, &AuditOutcome::rel_error_extreme);
  s.extrapolated_999 = stats_of(outcomes, &AuditOutcome::rel_error_extrapolated_999);
  s.coverage = judged > 0 ? static_cast<double>(s.covered) / judged : kNaN;
  return s;
}

}  // namespace towdb::cli
