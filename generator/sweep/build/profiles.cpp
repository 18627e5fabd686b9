#include "sweep/build/profiles.hpp"

#include <algorithm>
#include <map>
#include <cmath>

#include "common/error.hpp"
#include "common/parallel_for.hpp"
#include "store/packed_days.hpp"
#include "sweep/build/profile_stage.hpp"

namespace towdb::sweep {

namespace {

struct Line {
  std::string name;                   // for messages
  std::vector<std::size_t> members;   // indices into the sweep's cases, finished
  std::vector<std::int64_t> case_ids;
  std::string profile_key;            // 32 bytes
};

// The line a case belongs to: every input but the heading (and the days and
// seed, which the linear model does not read). Empty for a sea with swell.
std::string line_identity(const CaseSpec& s) {
  if (s.sea.swell) return {};
  auto num = [](const std::optional<double>& x) { return x ? canonical_number(*x) : std::string("-"); };
  return s.tug + "|" + s.tow + "|" + model::to_string(s.line) + "|" + canonical_number(s.length_ft) + "|" +
         canonical_number(s.speed_kt) + "|" + s.sea.spectrum_text() + "|" + num(s.sea.wind_kt) + "|" +
         num(s.sea.hs_ft) + "|" + num(s.sea.tp_s) + "|" + num(s.sea.gamma) + "|" +
         canonical_number(s.mean_tension_lbf);
}

double folded(double heading_deg) { return heading_deg > 180.0 ? 360.0 - heading_deg : heading_deg; }

// The finished cases of the sweep grouped into lines of two or more headings.
std::vector<Line> finished_lines(store::Database& db, const std::vector<CaseSpec>& cases,
                                 const std::vector<CaseKeys>& keys) {
  FinishedCases finished(db);
  std::map<std::string, Line> lines;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string id = line_identity(cases[i]);
    if (id.empty()) continue;
    const std::int64_t case_id = finished.case_id(keys[i]);
    if (case_id == 0) continue;
    Line& line = lines[id];
    line.name = id;
    line.members.push_back(i);
    line.case_ids.push_back(case_id);
  }
  std::vector<Line> out;
  for (auto& [id, line] : lines) {
    std::vector<double> headings;
    for (std::size_t i : line.members) headings.push_back(folded(cases[i].heading_deg));
    std::sort(headings.begin(), headings.end());
    if (std::unique(headings.begin(), headings.end()) - headings.begin() < 2) continue;
    std::vector<std::string> member_keys;
    for (std::size_t i : line.members) member_keys.push_back(keys[i].case_key);
    line.profile_key = line_profile_key(
        "heading-profile/2|" + canonical_number(kProfileStepDeg) + "|" + std::to_string(kProfileHeadings),
        std::move(member_keys));
    out.push_back(std::move(line));
  }
  return out;
}

void point_cases(store::Database& db, const Line& line, std::int64_t profile_id) {
  point_cases_at(db, "profile_id", line.case_ids, profile_id);
}

// The strip-theory responses dominate a profile's cost (two vessels, two
// speeds, every grid heading) and are cached process-wide, where a second
// thread asking for a response being computed waits for it. So before the
// lines, one profile heading per task for each (tug, tow, speed) among them
// fills the cache with every thread busy on a different heading; results and
// failures are discarded (the lines' own calls report them), and the stored
// numbers do not depend on it.
void warm_responses(const std::vector<Line>& lines, const std::vector<std::size_t>& work,
                    const std::vector<CaseSpec>& cases, const io::ShipCatalog& catalog,
                    const HeadingProfileFn& profile, const std::vector<double>& headings, int threads,
                    const std::atomic<bool>* stop) {
  std::map<std::string, std::size_t> first_of;  // "tug|tow|speed" -> a case of a line to compute
  for (std::size_t l : work) {
    const CaseSpec& c = cases[lines[l].members.front()];
    first_of.try_emplace(c.tug + "|" + c.tow + "|" + canonical_number(c.speed_kt), lines[l].members.front());
  }
  std::vector<std::size_t> representative;
  for (const auto& [key, i] : first_of) representative.push_back(i);
  const auto n = static_cast<std::int64_t>(representative.size() * headings.size());
  parallel_for(0, n, threads, [&](std::int64_t t) {
    if (stop && stop->load()) return;
    const CaseSpec& c = cases[representative[static_cast<std::size_t>(t) / headings.size()]];
    try {
      profile(c, catalog, {headings[static_cast<std::size_t>(t) % headings.size()]});
    } catch (const std::exception&) {
      // reported by the line's own profile below
    }
  });
}

// The line's profile [kips], checked finite and > 0, packed as binary32.
std::string compute_profile(const Line& line, const std::vector<CaseSpec>& cases, const io::ShipCatalog& catalog,
                            const HeadingProfileFn& profile, const std::vector<double>& headings) {
  return store::pack_float32(checked_sigma_kips(profile(cases[line.members.front()], catalog, headings)));
}

// Stores one line's profile and points its cases at it.
void write_profile(store::Database& db, const Line& line, double mean_tension_lbf, const std::string& sigma_f32,
                   std::int64_t build_id) {
  store::Statement insert = db.prepare(
      "INSERT INTO heading_profiles (profile_key, mean_tension_lbf, heading_first_deg, heading_step_deg, "
      "headings, sigma_kips_f32, build_id) VALUES (?, ?, ?, ?, ?, ?, ?)");
  insert.bind_blob(1, line.profile_key)
      .bind(2, mean_tension_lbf)
      .bind(3, 0.0)
      .bind(4, kProfileStepDeg)
      .bind(5, kProfileHeadings)
      .bind_blob(6, sigma_f32)
      .bind(7, build_id);
  insert.run();
  point_cases(db, line, db.last_insert_rowid());
}

}  // namespace

ProfileSummary update_heading_profiles(store::Database& db, const std::vector<CaseSpec>& cases,
                                       const std::vector<CaseKeys>& keys, const io::ShipCatalog& catalog,
                                       const HeadingProfileFn& profile, int threads, std::int64_t build_id,
                                       const std::atomic<bool>* stop) {
  if (!profile) throw InputError("heading profiles: no profile function was given");
  ProfileSummary summary;
  std::vector<Line> lines = finished_lines(db, cases, keys);
  summary.lines = static_cast<int>(lines.size());
  store::Statement find = db.prepare("SELECT profile_id FROM heading_profiles WHERE profile_key = ?");
  std::vector<std::size_t> work;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    find.reset();
    find.bind_blob(1, lines[l].profile_key);
    if (find.step()) {
      const std::int64_t stored = find.column_int(0);
      db.transaction([&] { point_cases(db, lines[l], stored); });
      ++summary.up_to_date;
    } else {
      work.push_back(l);
    }
  }
  std::vector<double> headings(kProfileHeadings);
  for (int j = 0; j < kProfileHeadings; ++j) headings[j] = kProfileStepDeg * j;
  warm_responses(lines, work, cases, catalog, profile, headings, threads, stop);
  // Lines in the order of their vessels and speeds (std::map's order above),
  // so the strip-theory responses each computes are reused while cached.
  StageWork stage;
  stage.count = work.size();
  stage.compute = [&](std::size_t w) { return compute_profile(lines[work[w]], cases, catalog, profile, headings); };
  stage.write = [&](std::size_t w, const std::string& blob) {
    const Line& line = lines[work[w]];
    write_profile(db, line, cases[line.members.front()].mean_tension_lbf, blob, build_id);
  };
  stage.clear = [&](std::size_t w) { point_cases(db, lines[work[w]], 0); };
  stage.name = [&](std::size_t w) {
    return lines[work[w]].name + " (first case_id " + std::to_string(lines[work[w]].case_ids.front()) + ")";
  };
  run_stage_chunks(db, stage, threads, stop, summary);
  db.exec(
      "DELETE FROM heading_profiles WHERE profile_id NOT IN "
      "(SELECT profile_id FROM cases WHERE profile_id IS NOT NULL)");
  return summary;
}

}  // namespace towdb::sweep
