#include "sweep/build/speed_profiles.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "common/error.hpp"
#include "common/parallel_for.hpp"
#include "store/packed_days.hpp"
#include "sweep/build/profile_stage.hpp"

namespace towdb::sweep {

namespace {

struct SpeedLine {
  std::string name;                  // for messages
  std::vector<std::size_t> members;  // indices into the sweep's cases, finished, ascending speed
  std::vector<std::int64_t> case_ids;
  std::vector<SpeedPoint> points;
  std::string profile_key;  // 32 bytes
};

// The line a case belongs to: every input but the speed and the mean tension
// that goes with it (and the days and seed, which the linear model does not
// read), with the sweep entry and mean-tension label that chose the tension
// (one rule per label within an entry). Empty for a sea with swell.
std::string speed_line_identity(const CaseSpec& s) {
  if (s.sea.swell) return {};
  auto num = [](const std::optional<double>& x) { return x ? canonical_number(*x) : std::string("-"); };
  const double heading = s.heading_deg > 180.0 ? 360.0 - s.heading_deg : s.heading_deg;
  return s.tug + "|" + s.tow + "|" + model::to_string(s.line) + "|" + canonical_number(s.length_ft) + "|" +
         s.sea.spectrum_text() + "|" + num(s.sea.wind_kt) + "|" + num(s.sea.hs_ft) + "|" + num(s.sea.tp_s) + "|" +
         num(s.sea.gamma) + "|" + canonical_number(heading) + "|" + s.sweep_label + "|" + s.mean_tension_label;
}

// The finished cases of the sweep grouped into lines of two or more distinct
// speeds. Cases at one speed with the same mean tension (headings h and
// 360 - h, folded into one line) share a point; a line with two mean tensions
// at one speed is left out.
std::vector<SpeedLine> finished_speed_lines(store::Database& db, const std::vector<CaseSpec>& cases,
                                            const std::vector<CaseKeys>& keys) {
  FinishedCases finished(db);
  std::map<std::string, std::vector<std::pair<std::size_t, std::int64_t>>> groups;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::string id = speed_line_identity(cases[i]);
    if (id.empty()) continue;
    const std::int64_t case_id = finished.case_id(keys[i]);
    if (case_id != 0) groups[std::move(id)].emplace_back(i, case_id);
  }
  std::vector<SpeedLine> out;
  for (auto& [id, members] : groups) {
    std::sort(members.begin(), members.end(),
              [&](const auto& a, const auto& b) { return cases[a.first].speed_kt < cases[b.first].speed_kt; });
    SpeedLine line;
    line.name = id;
    std::vector<double> speeds, means;
    std::vector<std::string> member_keys;
    bool ambiguous = false;
    for (const auto& [i, case_id] : members) {
      line.members.push_back(i);
      line.case_ids.push_back(case_id);
      member_keys.push_back(keys[i].case_key);
      if (!speeds.empty() && speeds.back() == cases[i].speed_kt) {
        ambiguous = ambiguous || means.back() != cases[i].mean_tension_lbf;
        continue;
      }
      speeds.push_back(cases[i].speed_kt);
      means.push_back(cases[i].mean_tension_lbf);
    }
    if (speeds.size() < 2 || ambiguous) continue;
    line.points = speed_profile_points(speeds, means);
    line.profile_key =
        line_profile_key("speed-profile/2|" + canonical_number(kSpeedProfileStepKt), std::move(member_keys));
    out.push_back(std::move(line));
  }
  return out;
}

void point_cases(store::Database& db, const SpeedLine& line, std::int64_t profile_id) {
  point_cases_at(db, "speed_profile_id", line.case_ids, profile_id);
}

// As warm_responses of the heading profiles (profiles.cpp): the strip-theory
// responses of each (tug, tow, heading, speed) among the lines' points are
// computed first, one point per task, so that no two threads wait on one
// response; results and failures are discarded (the lines report theirs).
void warm_responses(const std::vector<SpeedLine>& lines, const std::vector<std::size_t>& work,
                    const std::vector<CaseSpec>& cases, const io::ShipCatalog& catalog,
                    const SpeedProfileFn& profile, int threads, const std::atomic<bool>* stop) {
  std::map<std::string, std::pair<std::size_t, std::size_t>> first_of;  // -> (line, point)
  for (std::size_t l : work) {
    const CaseSpec& c = cases[lines[l].members.front()];
    for (std::size_t p = 0; p < lines[l].points.size(); ++p) {
      first_of.try_emplace(c.tug + "|" + c.tow + "|" + canonical_number(c.heading_deg) + "|" +
                               canonical_number(lines[l].points[p].speed_kt),
                           l, p);
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> tasks;
  for (const auto& [key, task] : first_of) tasks.push_back(task);
  parallel_for(0, static_cast<std::int64_t>(tasks.size()), threads, [&](std::int64_t t) {
    if (stop && stop->load()) return;
    const auto [l, p] = tasks[static_cast<std::size_t>(t)];
    try {
      profile(cases[lines[l].members.front()], catalog, {lines[l].points[p]});
    } catch (const std::exception&) {
      // reported by the line's own profile below
    }
  });
}

// The line's profile [kips], checked finite and > 0, packed as binary16.
std::string compute_profile(const SpeedLine& line, const std::vector<CaseSpec>& cases, const io::ShipCatalog& catalog,
                            const SpeedProfileFn& profile) {
  const std::vector<double> sigma_kips = checked_sigma_kips(profile(cases[line.members.front()], catalog, line.points));
  if (sigma_kips.size() != line.points.size()) {
    throw NumericalError("speed profile of " + std::to_string(sigma_kips.size()) + " values for " +
                         std::to_string(line.points.size()) + " speeds");
  }
  std::string packed;
  if (!store::pack_float16(sigma_kips, &packed)) {
    throw NumericalError("linear dynamic-tension sigma above binary16's 65,504 kips");
  }
  return packed;
}

// Stores one line's profile and points its cases at it.
void write_profile(store::Database& db, const SpeedLine& line, const std::string& sigma_f16, std::int64_t build_id) {
  store::Statement insert = db.prepare(
      "INSERT INTO speed_profiles (profile_key, speed_first_kt, speed_step_kt, speeds, sigma_kips_f16, build_id) "
      "VALUES (?, ?, ?, ?, ?, ?)");
  const auto n = line.points.size();
  insert.bind_blob(1, line.profile_key)
      .bind(2, line.points.front().speed_kt)
      .bind(3, (line.points.back().speed_kt - line.points.front().speed_kt) / static_cast<double>(n - 1))
      .bind(4, static_cast<std::int64_t>(n))
      .bind_blob(5, sigma_f16)
      .bind(6, build_id);
  insert.run();
  point_cases(db, line, db.last_insert_rowid());
}

}  // namespace

std::vector<SpeedPoint> speed_profile_points(const std::vector<double>& speeds_kt,
                                             const std::vector<double>& mean_tensions_lbf) {
  if (speeds_kt.size() < 2 || speeds_kt.size() != mean_tensions_lbf.size()) {
    throw InputError("speed profile: " + std::to_string(speeds_kt.size()) + " speeds and " +
                     std::to_string(mean_tensions_lbf.size()) + " mean tensions; allowed: two or more of each, as many");
  }
  for (std::size_t i = 0; i < speeds_kt.size(); ++i) {
    if (!(speeds_kt[i] > 0.0) || (i > 0 && !(speeds_kt[i] > speeds_kt[i - 1]))) {
      throw InputError("speed profile: speed_kt = " + format_value(speeds_kt[i]) +
                       "; allowed: > 0 and ascending, each speed once");
    }
    if (!(mean_tensions_lbf[i] > 0.0 && std::isfinite(mean_tensions_lbf[i]))) {
      throw InputError("speed profile: mean_tension_lbf = " + format_value(mean_tensions_lbf[i]) + "; allowed: > 0");
    }
  }
  const double first = speeds_kt.front(), last = speeds_kt.back();
  // Exact multiples of the step stay exact (1e-9: a span written in decimal).
  const auto n = static_cast<std::size_t>(std::ceil((last - first) / kSpeedProfileStepKt - 1e-9)) + 1;
  std::vector<SpeedPoint> points(n);
  std::size_t i = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const double v = j + 1 == n ? last : first + (last - first) * static_cast<double>(j) / static_cast<double>(n - 1);
    while (i + 2 < speeds_kt.size() && v > speeds_kt[i + 1]) ++i;
    const double t = std::clamp((v - speeds_kt[i]) / (speeds_kt[i + 1] - speeds_kt[i]), 0.0, 1.0);
    const double m0 = mean_tensions_lbf[i], m1 = mean_tensions_lbf[i + 1];
    points[j].speed_kt = v;
    // Ends and equal tensions exact (a given tension stays its bits).
    points[j].mean_tension_lbf = t == 0.0 || m0 == m1 ? m0
                                 : t == 1.0             ? m1
                                                        : std::exp((1.0 - t) * std::log(m0) + t * std::log(m1));
  }
  return points;
}

ProfileSummary update_speed_profiles(store::Database& db, const std::vector<CaseSpec>& cases,
                                     const std::vector<CaseKeys>& keys, const io::ShipCatalog& catalog,
                                     const SpeedProfileFn& profile, int threads, std::int64_t build_id,
                                     const std::atomic<bool>* stop) {
  if (!profile) throw InputError("speed profiles: no profile function was given");
  ProfileSummary summary;
  std::vector<SpeedLine> lines = finished_speed_lines(db, cases, keys);
  summary.lines = static_cast<int>(lines.size());
  std::map<std::string, std::int64_t> stored;  // profile_key -> speed_profile_id
  {
    store::Statement all = db.prepare("SELECT profile_key, speed_profile_id FROM speed_profiles");
    while (all.step()) stored.emplace(all.column_blob(0), all.column_int(1));
  }
  std::vector<std::size_t> work;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const auto it = stored.find(lines[l].profile_key);
    if (it != stored.end()) {
      db.transaction([&] { point_cases(db, lines[l], it->second); });
      ++summary.up_to_date;
    } else {
      work.push_back(l);
    }
  }
  warm_responses(lines, work, cases, catalog, profile, threads, stop);
  // Lines in the order of their identities (std::map's order above).
  StageWork stage;
  stage.count = work.size();
  stage.compute = [&](std::size_t w) { return compute_profile(lines[work[w]], cases, catalog, profile); };
  stage.write = [&](std::size_t w, const std::string& blob) { write_profile(db, lines[work[w]], blob, build_id); };
  stage.clear = [&](std::size_t w) { point_cases(db, lines[work[w]], 0); };
  stage.name = [&](std::size_t w) {
    return lines[work[w]].name + " (first case_id " + std::to_string(lines[work[w]].case_ids.front()) + ")";
  };
  run_stage_chunks(db, stage, threads, stop, summary);
  db.exec(
      "DELETE FROM speed_profiles WHERE speed_profile_id NOT IN "
      "(SELECT speed_profile_id FROM cases WHERE speed_profile_id IS NOT NULL)");
  return summary;
}

}  // namespace towdb::sweep
