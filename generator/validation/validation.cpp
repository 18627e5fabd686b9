#include "validation/validation.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <sstream>

#include "common/error.hpp"
#include "common/parallel_for.hpp"
#include "common/units.hpp"
#include "io/csv.hpp"
#include "sea/spectrum.hpp"

namespace towdb::validation {

namespace {

model::LineKind line_kind(const std::string& line) {
  if (line == "wire") return model::LineKind::kWire;
  if (line == "fiber") return model::LineKind::kFiber;
  throw InputError("line = '" + line + "': expected wire or fiber");
}

std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == ',') c = ';';
    if (c == '\n' || c == '\r' || c == '"') c = ' ';
  }
  return text;
}

std::string number17(double v) {
  std::ostringstream os;
  os << std::setprecision(17) << v;
  return os.str();
}

std::string fixed(double v, int digits) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream os;
  os << std::fixed << std::setprecision(digits) << v;
  return os.str();
}

std::string percent(double share) { return std::isfinite(share) ? fixed(100.0 * share, 0) + " %" : "n/a"; }

bool parse_double(const std::string& s, double& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

bool parse_int(const std::string& s, int& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

constexpr const char* kJournalHeader =
    "case,tug,tow,speed_kt,wind_kt,heading_deg,length_ft,line,mean_lbf,days,dyn_kips,days_run,status,ours_kips,"
    "ratio,ci_low_kips,ci_high_kips,hs_ft,slack_fraction,above_breaking,runtime_s,extension_sd_ft,extension_min_ft,"
    "extension_max_ft,fit_min_ft,fit_max_ft,days_outside_fit,error";
constexpr std::size_t kJournalColumns = 28;

template <class Key>
std::vector<Agreement> grouped(const std::vector<const CaseOutcome*>& cases, const std::string& prefix, Key key) {
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> groups;
  for (const CaseOutcome* c : cases) {
    auto& g = groups[key(*c)];
    g.first.push_back(c->ours_kips);
    g.second.push_back(c->row.dynamic_999_kips);
  }
  std::vector<Agreement> out;
  for (const auto& [name, g] : groups) out.push_back(agreement(prefix + name, g.first, g.second));
  return out;
}

void agreement_table(std::ostringstream& os, const std::vector<Agreement>& rows) {
  os << "| group | n | median ratio | geometric mean | log rms | Spearman | within 1.5x | within 2x |\n"
     << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Agreement& a : rows) {
    if (a.count == 0) continue;
    os << "| " << a.group << " | " << a.count << " | " << fixed(a.median_ratio, 3) << " | "
       << fixed(a.geometric_mean_ratio, 3) << " | " << fixed(a.log_rms, 3) << " | " << fixed(a.spearman, 3) << " | "
       << percent(a.within_1_5) << " | " << percent(a.within_2) << " |\n";
  }
  os << "\n";
}

}  // namespace

void RunOptions::validate() const {
  require_input(std::isfinite(days_scale) && days_scale > 0.0 && days_scale <= 10.0, "RunOptions::days_scale",
                days_scale, "a number in (0, 10]");
  require_input(min_days >= 10 && min_days <= 1000000, "RunOptions::min_days", min_days,
                "an integer in [10, 1e6] (the case statistics fit a GEV to >= 10 daily maxima)");
  require_input(response_frequencies >= 8 && response_frequencies <= 400, "RunOptions::response_frequencies",
                response_frequencies, "an integer in [8, 400]");
  require_input(num_threads <= 1024, "RunOptions::num_threads", num_threads, "<= 1024 (<= 0: all cores)");
  require_input(std::isfinite(encounter_cutoff_rad_s) && encounter_cutoff_rad_s >= 1.0 &&
                    encounter_cutoff_rad_s <= simulation::kEncounterCutoff_rad_s,
                "RunOptions::encounter_cutoff_rad_s", encounter_cutoff_rad_s,
                "a number in [1, 3] rad/s (the transfer functions end at 3 rad/s)");
}

int simulated_days(const sweep::CalibrationRow& row, const RunOptions& options) {
  const double scaled = std::round(options.days_scale * static_cast<double>(row.days));
  return std::max(options.min_days, static_cast<int>(scaled));
}

simulation::CaseInputs case_inputs(const sweep::CalibrationRow& row, const io::ShipCatalog& catalog, int days) {
  const model::Vessel& tug = catalog.vessel(row.tug).vessel;
  const model::Vessel& tow = catalog.vessel(row.tow).vessel;
  if (tug.role != model::VesselRole::kTug) {
    throw InputError("case " + std::to_string(row.case_number) + ": tug '" + row.tug + "' is not a tug");
  }
  simulation::CaseInputs in;
  in.tug = &tug;
  in.tow = &tow;
  in.towline = catalog.towline(tug, line_kind(row.line), units::ft_to_m(row.length_ft));
  in.speed_m_s = units::kt_to_m_s(row.speed_kt);
  in.sea = sea::single_system(sea::Spectrum::pierson_moskowitz(units::kt_to_m_s(row.wind_kt)),
                              units::deg_to_rad(row.heading_deg));
  in.mean_tension_n = units::lbf_to_n(row.mean_tension_lbf);
  in.days = days;
  in.seed = static_cast<std::uint64_t>(row.case_number);
  return in;
}

simulation::CaseOptions case_options(const RunOptions& options) {
  simulation::CaseOptions o;
  o.num_threads = 1;
  o.response_frequencies = options.response_frequencies;
  o.second_order_forces = options.second_order_forces;
  o.wave_surge_damping = options.wave_surge_damping;
  o.tow_drift_at_tow = options.tow_drift_at_tow;
  o.response.added_resistance_aft_of_beam = options.added_resistance_aft_of_beam;
  o.signed_drift = options.signed_drift;
  o.linear_non_surge_tension = options.linear_non_surge_tension;
  o.non_surge_stiffness = options.non_surge_stiffness;
  o.nonnegative_wave_damping = options.nonnegative_wave_damping;
  o.record.encounter_cutoff_rad_s = options.encounter_cutoff_rad_s;
  o.response.surge_diffraction = options.surge_diffraction;
  if (options.thesis_towline_fit) {
    o.towline.hold_static_stiffness = false;
    o.towline.max_run_weight_exponent = 0.0;
  }
  return o;
}

CaseOutcome run_one(const sweep::CalibrationRow& row, const io::ShipCatalog& catalog, const RunOptions& options) {
  CaseOutcome out;
  out.row = row;
  out.days_run = simulated_days(row, options);
  const auto start = std::chrono::steady_clock::now();
  try {
    const simulation::CaseInputs in = case_inputs(row, catalog, out.days_run);
    out.hs_ft = units::m_to_ft(in.sea.significant_height_m());
    const simulation::CaseResult r = simulation::run_case(in, case_options(options));
    out.ours_kips = units::n_to_kips(r.statistics.dynamic_999_n);
    out.ci_low_kips = units::n_to_kips(r.statistics.ci_low_n);
    out.ci_high_kips = units::n_to_kips(r.statistics.ci_high_n);
    out.slack_fraction = r.slack_fraction;
    out.above_breaking = r.above_breaking_strength;
    out.extension_sd_ft = units::m_to_ft(r.extension.sd_m);
    out.extension_min_ft = units::m_to_ft(r.extension.min_m);
    out.extension_max_ft = units::m_to_ft(r.extension.max_m);
    out.fit_min_ft = units::m_to_ft(r.towline.fit_xi_min_m);
    out.fit_max_ft = units::m_to_ft(r.towline.fit_xi_max_m);
    out.days_outside_fit = r.extension.days_outside_fit;
    if (!(std::isfinite(out.ours_kips) && out.ours_kips > 0.0)) {
      throw NumericalError("validation: dynamic tension = " + format_value(out.ours_kips) + " kips is not positive");
    }
    out.status = CaseStatus::kOk;
  } catch (const std::exception& e) {
    out.status = CaseStatus::kFailed;
    out.error = one_line(e.what());
    out.ours_kips = 0.0;
  }
  out.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::vector<CaseOutcome> run_all(const std::vector<sweep::CalibrationRow>& rows, const io::ShipCatalog& catalog,
                                 const RunOptions& options, const std::vector<CaseOutcome>& done,
                                 const OutcomeCallback& on_outcome) {
  options.validate();
  std::vector<CaseOutcome> out(rows.size());
  std::vector<std::int64_t> todo;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const int days = simulated_days(rows[i], options);
    const auto it = std::find_if(done.begin(), done.end(), [&](const CaseOutcome& d) {
      return d.status == CaseStatus::kOk && d.row.case_number == rows[i].case_number && d.days_run == days;
    });
    if (it != done.end()) {
      out[i] = *it;
      out[i].row = rows[i];
    } else {
      todo.push_back(static_cast<std::int64_t>(i));
    }
  }
  std::mutex mutex;
  int finished = static_cast<int>(rows.size() - todo.size());
  const int total = static_cast<int>(rows.size());
  parallel_for(0, static_cast<std::int64_t>(todo.size()), options.num_threads, [&](std::int64_t k) {
    const std::size_t i = static_cast<std::size_t>(todo[static_cast<std::size_t>(k)]);
    out[i] = run_one(rows[i], catalog, options);
    if (on_outcome) {
      const std::lock_guard<std::mutex> lock(mutex);
      on_outcome(out[i], ++finished, total);
    }
  });
  return out;
}

double median(std::vector<double> values) {
  if (values.empty()) throw InputError("median: the sample is empty");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<double> average_ranks(std::span<const double> values) {
  const std::size_t n = values.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> ranks(n);
  std::size_t i = 0;
  while (i < n) {
    std::size_t j = i + 1;
    while (j < n && values[order[j]] == values[order[i]]) ++j;
    // Positions i..j-1 hold equal values: ranks i+1..j, average (i + 1 + j) / 2.
    const double rank = 0.5 * static_cast<double>(i + 1 + j);
    for (std::size_t k = i; k < j; ++k) ranks[order[k]] = rank;
    i = j;
  }
  return ranks;
}

double spearman_rank_correlation(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size()) {
    throw InputError("spearman_rank_correlation: sizes " + std::to_string(x.size()) + " and " +
                     std::to_string(y.size()) + " differ");
  }
  if (x.size() < 2) throw InputError("spearman_rank_correlation: n = " + std::to_string(x.size()) + ", need >= 2");
  const std::vector<double> rx = average_ranks(x), ry = average_ranks(y);
  const double n = static_cast<double>(x.size());
  const double mean = 0.5 * (n + 1.0);  // the mean of any average-rank vector
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < rx.size(); ++i) {
    sxy += (rx[i] - mean) * (ry[i] - mean);
    sxx += (rx[i] - mean) * (rx[i] - mean);
    syy += (ry[i] - mean) * (ry[i] - mean);
  }
  if (sxx == 0.0 || syy == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return sxy / std::sqrt(sxx * syy);
}

Agreement agreement(const std::string& group, std::span<const double> ours, std::span<const double> thesis) {
  if (ours.size() != thesis.size()) {
    throw InputError("agreement(" + group + "): sizes " + std::to_string(ours.size()) + " and " +
                     std::to_string(thesis.size()) + " differ");
  }
  if (ours.empty()) throw InputError("agreement(" + group + "): no cases");
  Agreement a;
  a.group = group;
  a.count = static_cast<int>(ours.size());
  std::vector<double> ratios;
  double sum_log = 0.0, sum_log2 = 0.0;
  int in15 = 0, in2 = 0;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    if (!(ours[i] > 0.0 && thesis[i] > 0.0 && std::isfinite(ours[i]) && std::isfinite(thesis[i]))) {
      throw InputError("agreement(" + group + "): values must be positive and finite, found ours = " +
                       format_value(ours[i]) + ", thesis = " + format_value(thesis[i]));
    }
    const double r = ours[i] / thesis[i];
    ratios.push_back(r);
    const double l = std::log(r);
    sum_log += l;
    sum_log2 += l * l;
    if (r >= 1.0 / 1.5 && r <= 1.5) ++in15;
    if (r >= 0.5 && r <= 2.0) ++in2;
  }
  const double n = static_cast<double>(ours.size());
  a.median_ratio = median(ratios);
  a.geometric_mean_ratio = std::exp(sum_log / n);
  a.log_rms = std::sqrt(sum_log2 / n);
  a.spearman = ours.size() >= 3 ? spearman_rank_correlation(ours, thesis) : std::numeric_limits<double>::quiet_NaN();
  a.within_1_5 = in15 / n;
  a.within_2 = in2 / n;
  return a;
}

// A heading as a group key, zero-padded so that a map orders 0, 60, 120, 180: "060 deg".
std::string heading_key(double heading_deg) {
  std::ostringstream os;
  os << std::setw(3) << std::setfill('0') << std::lround(heading_deg) << " deg";
  return os.str();
}

// Report::extension_by_line_heading over the simulated cases among `cases`.
std::vector<Report::ExtensionGroup> extension_groups(const std::vector<const CaseOutcome*>& cases) {
  std::map<std::string, std::vector<const CaseOutcome*>> groups;
  for (const CaseOutcome* c : cases) {
    if (!std::isfinite(c->extension_sd_ft)) continue;  // not simulated
    groups[c->row.line + " " + heading_key(c->row.heading_deg)].push_back(c);
  }
  std::vector<Report::ExtensionGroup> out;
  for (const auto& [name, members] : groups) {
    Report::ExtensionGroup g;
    g.group = name;
    g.count = static_cast<int>(members.size());
    std::vector<double> ratio, sd, reach;
    for (const CaseOutcome* c : members) {
      ratio.push_back(c->ratio());
      sd.push_back(c->extension_sd_ft);
      reach.push_back(std::max(c->extension_min_ft / c->fit_min_ft, c->extension_max_ft / c->fit_max_ft));
      g.cases_outside_fit += c->days_outside_fit > 0;
      g.cases_slack += c->slack_fraction > 0.0;
    }
    g.median_ratio = median(ratio);
    g.median_sd_ft = median(sd);
    g.median_reach = median(reach);
    out.push_back(g);
  }
  return out;
}

Report make_report(std::vector<CaseOutcome> outcomes, const Targets& targets) {
  Report rep;
  rep.outcomes = std::move(outcomes);
  std::vector<const CaseOutcome*> valid, above, ok;
  for (const CaseOutcome& c : rep.outcomes) {
    if (c.status != CaseStatus::kOk) {
      ++rep.failed;
      continue;
    }
    ok.push_back(&c);
    (c.row.dynamic_999_kips > kThesisValidityLimitKips ? above : valid).push_back(&c);
  }
  const auto summary = [](const std::string& name, const std::vector<const CaseOutcome*>& cases) {
    if (cases.empty()) {
      Agreement a;
      a.group = name;
      return a;
    }
    std::vector<double> o, t;
    for (const CaseOutcome* c : cases) {
      o.push_back(c->ours_kips);
      t.push_back(c->row.dynamic_999_kips);
    }
    return agreement(name, o, t);
  };
  rep.valid = summary("thesis <= 300 kips", valid);
  rep.above_limit = summary("thesis > 300 kips", above);
  rep.all = summary("all cases", ok);
  rep.by_tow = grouped(valid, "tow ", [](const CaseOutcome& c) { return c.row.tow; });
  rep.by_tug = grouped(valid, "tug ", [](const CaseOutcome& c) { return c.row.tug; });
  rep.by_line = grouped(valid, "line ", [](const CaseOutcome& c) { return c.row.line; });
  rep.by_heading = grouped(valid, "heading ", [](const CaseOutcome& c) { return heading_key(c.row.heading_deg); });
  rep.by_wind = grouped(valid, "wind ", [](const CaseOutcome& c) { return fixed(c.row.wind_kt, 0) + " kt"; });
  rep.extension_by_line_heading = extension_groups(valid);
  if (rep.valid.count > 0) {
    rep.median_ok = rep.valid.median_ratio >= targets.median_low && rep.valid.median_ratio <= targets.median_high;
    rep.spearman_ok = rep.valid.spearman >= targets.spearman_min;
    rep.within_ok = rep.valid.within_1_5 >= targets.within_1_5_min;
  }
  return rep;
}

std::string report_markdown(const Report& rep, const std::string& run_note, const Targets& targets) {
  std::ostringstream os;
  const auto mark = [](bool ok) { return ok ? "met" : "**missed**"; };
  os << "# towdb validation against the thesis database (Desroches 1997, Appendix C)\n\n"
     << run_note << "\n\n"
     << "Cases: " << rep.outcomes.size() << " (" << rep.valid.count << " with the thesis tension <= "
     << fixed(kThesisValidityLimitKips, 0) << " kips, " << rep.above_limit.count << " above, " << rep.failed
     << " failed).\n"
     << "Ratio = ours / thesis, dynamic tension with 0.001 chance of exceedance in one day (Type I).\n\n"
     << "## Targets (cases <= " << fixed(kThesisValidityLimitKips, 0) << " kips)\n\n"
     << "| measure | value | target | |\n|---|---:|---|---|\n"
     << "| median ratio | " << fixed(rep.valid.median_ratio, 3) << " | " << fixed(targets.median_low, 2) << " - "
     << fixed(targets.median_high, 2) << " | " << mark(rep.median_ok) << " |\n"
     << "| Spearman rank correlation | " << fixed(rep.valid.spearman, 3) << " | >= " << fixed(targets.spearman_min, 2)
     << " | " << mark(rep.spearman_ok) << " |\n"
     << "| within a factor 1.5 | " << percent(rep.valid.within_1_5) << " | >= "
     << percent(targets.within_1_5_min) << " | " << mark(rep.within_ok) << " |\n"
     << "| within a factor 2 | " << percent(rep.valid.within_2) << " | | |\n\n"
     << "## Overall\n\n";
  agreement_table(os, {rep.valid, rep.above_limit, rep.all});
  os << "## By tow (<= 300 kips)\n\n";
  agreement_table(os, rep.by_tow);
  os << "## By tug (<= 300 kips)\n\n";
  agreement_table(os, rep.by_tug);
  os << "## By line type (<= 300 kips)\n\n";
  agreement_table(os, rep.by_line);
  os << "## By heading (<= 300 kips; 0 = following seas, 180 = head seas)\n\n";
  agreement_table(os, rep.by_heading);
  os << "## By wind speed (<= 300 kips)\n\n";
  agreement_table(os, rep.by_wind);
  if (!rep.extension_by_line_heading.empty()) {
    os << "## The line's extension by line type and heading (<= 300 kips)\n\n"
       << "Reach: the largest excursion over the fitted half-range on its side (above 1: the polynomial was "
          "continued linearly, EQ-CASE-1).\n\n"
       << "| group | cases | median ratio | extension sd ft (median) | reach (median) | cases outside the fitted "
          "range | cases ever slack |\n|---|---:|---:|---:|---:|---:|---:|\n";
    for (const Report::ExtensionGroup& g : rep.extension_by_line_heading) {
      os << "| " << g.group << " | " << g.count << " | " << fixed(g.median_ratio, 2) << " | "
         << fixed(g.median_sd_ft, 1) << " | " << fixed(g.median_reach, 2) << " | " << g.cases_outside_fit << " | "
         << g.cases_slack << " |\n";
    }
    os << "\n";
  }

  std::vector<const CaseOutcome*> ok;
  for (const CaseOutcome& c : rep.outcomes) {
    if (c.status == CaseStatus::kOk) ok.push_back(&c);
  }
  const auto case_row = [](std::ostringstream& s, const CaseOutcome& c) {
    s << "| " << c.row.case_number << " | " << c.row.tug << " | " << c.row.tow << " | " << fixed(c.row.speed_kt, 0)
      << " | " << fixed(c.row.wind_kt, 0) << " | " << fixed(c.row.heading_deg, 0) << " | "
      << fixed(c.row.length_ft, 0) << " " << c.row.line << " | " << fixed(c.row.mean_tension_lbf / 1000.0, 1)
      << " | " << c.days_run << " | " << fixed(c.row.dynamic_999_kips, 1) << " | " << fixed(c.ours_kips, 1) << " | "
      << fixed(c.ratio(), 2) << " |\n";
  };
  const char* case_header =
      "| case | tug | tow | kt | wind kt | heading | hawser ft | mean kips | days | thesis kips | ours kips | ratio |\n"
      "|---:|---|---|---:|---:|---:|---|---:|---:|---:|---:|---:|\n";
  std::vector<const CaseOutcome*> worst;
  for (const CaseOutcome* c : ok) {
    if (c->row.dynamic_999_kips <= kThesisValidityLimitKips) worst.push_back(c);
  }
  std::stable_sort(worst.begin(), worst.end(), [](const CaseOutcome* a, const CaseOutcome* b) {
    return std::fabs(std::log(a->ratio())) > std::fabs(std::log(b->ratio()));
  });
  if (worst.size() > 15) worst.resize(15);
  os << "## Largest disagreements (<= 300 kips)\n\n" << case_header;
  for (const CaseOutcome* c : worst) case_row(os, *c);
  os << "\n## Cases above " << fixed(kThesisValidityLimitKips, 0)
     << " kips (thesis 6.2: outside the towline model's validity)\n\n"
     << case_header;
  for (const CaseOutcome* c : ok) {
    if (c->row.dynamic_999_kips > kThesisValidityLimitKips) case_row(os, *c);
  }
  os << "\n## Failed cases\n\n";
  if (rep.failed == 0) {
    os << "None.\n";
  } else {
    os << "| case | tug | tow | error |\n|---:|---|---|---|\n";
    for (const CaseOutcome& c : rep.outcomes) {
      if (c.status != CaseStatus::kOk) {
        os << "| " << c.row.case_number << " | " << c.row.tug << " | " << c.row.tow << " | " << c.error << " |\n";
      }
    }
  }
  return os.str();
}

std::string journal_header() { return kJournalHeader; }

std::string journal_line(const CaseOutcome& c) {
  std::ostringstream os;
  const sweep::CalibrationRow& r = c.row;
  os << r.case_number << "," << r.tug << "," << r.tow << "," << number17(r.speed_kt) << "," << number17(r.wind_kt)
     << "," << number17(r.heading_deg) << "," << number17(r.length_ft) << "," << r.line << ","
     << number17(r.mean_tension_lbf) << "," << r.days << "," << number17(r.dynamic_999_kips) << "," << c.days_run
     << "," << (c.status == CaseStatus::kOk ? "ok" : "failed") << "," << number17(c.ours_kips) << ","
     << number17(c.status == CaseStatus::kOk ? c.ratio() : 0.0) << "," << number17(c.ci_low_kips) << ","
     << number17(c.ci_high_kips) << "," << number17(c.hs_ft) << "," << number17(c.slack_fraction) << ","
     << (c.above_breaking ? 1 : 0) << "," << number17(c.runtime_s) << "," << number17(c.extension_sd_ft) << ","
     << number17(c.extension_min_ft) << "," << number17(c.extension_max_ft) << "," << number17(c.fit_min_ft) << ","
     << number17(c.fit_max_ft) << "," << c.days_outside_fit << "," << one_line(c.error);
  return os.str();
}

std::vector<CaseOutcome> parse_journal(const std::string& text) {
  std::vector<CaseOutcome> out;
  std::istringstream is(text);
  std::string line;
  bool header = true;
  while (std::getline(is, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (header) {
      header = false;
      if (line == kJournalHeader) continue;
    }
    const std::vector<std::string> f = io::csv::split_plain(line);
    if (f.size() != kJournalColumns) continue;
    CaseOutcome c;
    sweep::CalibrationRow& r = c.row;
    int above = 0;
    const bool ok = parse_int(f[0], r.case_number) && parse_double(f[3], r.speed_kt) &&
                    parse_double(f[4], r.wind_kt) && parse_double(f[5], r.heading_deg) &&
                    parse_double(f[6], r.length_ft) && parse_double(f[8], r.mean_tension_lbf) &&
                    parse_int(f[9], r.days) && parse_double(f[10], r.dynamic_999_kips) &&
                    parse_int(f[11], c.days_run) && (f[12] == "ok" || f[12] == "failed") &&
                    parse_double(f[13], c.ours_kips) && parse_double(f[15], c.ci_low_kips) &&
                    parse_double(f[16], c.ci_high_kips) && parse_double(f[17], c.hs_ft) &&
                    parse_double(f[18], c.slack_fraction) && parse_int(f[19], above) &&
                    parse_double(f[20], c.runtime_s) && parse_double(f[21], c.extension_sd_ft) &&
                    parse_double(f[22], c.extension_min_ft) && parse_double(f[23], c.extension_max_ft) &&
                    parse_double(f[24], c.fit_min_ft) && parse_double(f[25], c.fit_max_ft) &&
                    parse_int(f[26], c.days_outside_fit);
    if (!ok) continue;
    r.tug = f[1];
    r.tow = f[2];
    r.line = f[7];
    c.status = f[12] == "ok" ? CaseStatus::kOk : CaseStatus::kFailed;
    c.above_breaking = above != 0;
    c.error = f[27];
    out.push_back(c);
  }
  return out;
}

}  // namespace towdb::validation
