// Refinement driven by the error estimate: see refine.hpp.
#include "refine.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "common/error.hpp"
#include "database_basis.hpp"
#include "output.hpp"
#include "query_database.hpp"
#include "store/database.hpp"
#include "towdb/query.hpp"

namespace towdb::cli {

namespace {

constexpr std::array<RefineAxis, 4> kAxes = {RefineAxis::kSpeed, RefineAxis::kWind, RefineAxis::kHeading,
                                             RefineAxis::kLength};

// Stored node values of one (tug, tow, line) group, per axis (kAxes order).
struct Group {
  std::string tug, tow, line;
  std::array<std::set<double>, 4> values;
};

std::size_t slot(RefineAxis a) { return static_cast<std::size_t>(a); }

std::vector<Group> read_groups(const std::filesystem::path& db_path) {
  store::Database db = store::Database::open(db_path, store::Database::Mode::kReadOnly);
  store::Statement st = db.prepare(
      "SELECT DISTINCT tug_name, tow_name, line_type, speed_kt, wind_kt, heading_deg, length_ft FROM cases "
      "WHERE status = 'done' AND spectrum = 'pierson-moskowitz' AND wind_kt IS NOT NULL "
      "ORDER BY tug_name, tow_name, line_type");
  std::map<std::tuple<std::string, std::string, std::string>, Group> groups;
  while (st.step()) {
    Group& g = groups[{st.column_text(0), st.column_text(1), st.column_text(2)}];
    g.tug = st.column_text(0);
    g.tow = st.column_text(1);
    g.line = st.column_text(2);
    for (int a = 0; a < 4; ++a) g.values[static_cast<std::size_t>(a)].insert(st.column_double(3 + a));
  }
  std::vector<Group> out;
  for (auto& [key, g] : groups) out.push_back(std::move(g));
  return out;
}

// The sweep's first grid that holds the group; nullptr when none does.
const sweep::GridEntry* source_grid(const sweep::SweepFile& sweep, const Group& g) {
  for (const sweep::GridEntry& e : sweep.grids) {
    const bool tug = std::find(e.tugs.begin(), e.tugs.end(), g.tug) != e.tugs.end();
    const bool tow = std::find(e.tows.begin(), e.tows.end(), g.tow) != e.tows.end();
    const bool line = std::any_of(e.towlines.begin(), e.towlines.end(),
                                  [&](const sweep::TowlineChoice& c) { return model::to_string(c.line) == g.line; });
    if (tug && tow && line) return &e;
  }
  return nullptr;
}

// Every combination of the stored values of the axes other than `skip`.
std::vector<std::array<double, 4>> hyperplane(const Group& g, RefineAxis skip, double at) {
  std::vector<std::array<double, 4>> points = {{0.0, 0.0, 0.0, 0.0}};
  for (RefineAxis a : kAxes) {
    std::vector<std::array<double, 4>> next;
    for (const auto& p : points) {
      if (a == skip) {
        next.push_back(p);
        next.back()[slot(a)] = at;
        continue;
      }
      for (double v : g.values[slot(a)]) {
        next.push_back(p);
        next.back()[slot(a)] = v;
      }
    }
    points = std::move(next);
  }
  return points;
}

// The mean estimated relative error at mid-cell (EQ-QUERY-7), over the
// questions the database answers.
void score_cell(query::Database& db, const Group& g, CellScore* cell) {
  double sum = 0.0;
  for (const auto& p : hyperplane(g, cell->axis, 0.5 * (cell->lo + cell->hi))) {
    query::QueryRequest r;
    r.tug = g.tug;
    r.tow = g.tow;
    r.line = g.line;
    r.values.speed_kt = p[slot(RefineAxis::kSpeed)];
    r.values.wind_kt = p[slot(RefineAxis::kWind)];
    r.values.heading_deg = p[slot(RefineAxis::kHeading)];
    r.values.length_ft = p[slot(RefineAxis::kLength)];
    try {
      const towdb_query_result v = db.query(r).values;
      if (v.dynamic_999_kips > 0.0) {
        sum += v.interpolation_error_kips / v.dynamic_999_kips;
        ++cell->questions;
      }
    } catch (const query::QueryError& e) {
      if (!e.is_input()) throw;
      // A question the database refuses (e.g. a factor it does not store) adds nothing.
    }
  }
  cell->score = cell->questions > 0 ? sum / cell->questions : 0.0;
}

// The new grid of one group: the source grid's settings and levels, the
// group's stored values, `axis` replaced by the chosen midpoints.
sweep::GridEntry refinement_grid(const sweep::GridEntry& source, const Group& g, RefineAxis axis,
                                 const std::vector<double>& mids) {
  sweep::GridEntry e;
  e.label = "refine-" + std::string(axis_name(axis));
  e.tugs = {g.tug};
  e.tows = {g.tow};
  auto values = [&](RefineAxis a) {
    return a == axis ? mids : std::vector<double>(g.values[slot(a)].begin(), g.values[slot(a)].end());
  };
  e.speeds_kt = values(RefineAxis::kSpeed);
  for (double u : values(RefineAxis::kWind)) {
    sweep::SeaSpec sea;
    sea.wind_kt = u;
    e.seas.push_back(sea);
  }
  e.headings_deg = values(RefineAxis::kHeading);
  const model::LineKind kind = g.line == "wire" ? model::LineKind::kWire : model::LineKind::kFiber;
  for (double l : values(RefineAxis::kLength)) e.towlines.push_back({kind, l});
  e.mean_tensions = source.mean_tensions;
  e.days = source.days;
  e.base_seed = source.base_seed;
  e.mean_model = source.mean_model;
  return e;
}

// A TOML float that reads back to the same double (whole numbers as "5.0").
std::string toml_number(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15) return fmt(v, 1);
  return fmt(v);
}

std::string toml_list(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + toml_number(v[i]);
  return s + "]";
}

}  // namespace

const char* axis_name(RefineAxis axis) {
  switch (axis) {
    case RefineAxis::kSpeed: return "speed";
    case RefineAxis::kWind: return "wind";
    case RefineAxis::kHeading: return "heading";
    case RefineAxis::kLength: return "length";
  }
  return "?";
}

void RefineOptions::validate() const {
  if (!(threshold > 0.0 && threshold < 1.0)) {
    throw InputError("refine: threshold = " + fmt(threshold) + " is not allowed; allowed: a fraction in (0, 1)");
  }
  if (max_cases < 1) {
    throw InputError("refine: max_cases = " + std::to_string(max_cases) + " is not allowed; allowed: >= 1");
  }
  if (axes.empty()) throw InputError("refine: axes is empty; allowed: one or more of speed, wind, heading, length");
  if (std::set<RefineAxis>(axes.begin(), axes.end()).size() != axes.size()) {
    throw InputError("refine: axes names an axis twice");
  }
}

RefinePlan plan_refinement(const std::filesystem::path& db_path, const sweep::SweepFile& sweep,
                           const RefineOptions& options) {
  options.validate();
  const std::vector<Group> groups = read_groups(db_path);
  const std::unique_ptr<query::Database> opened = open_query_database("--db", db_path.string());
  query::Database& db = *opened;
  RefinePlan plan;
  for (const Group& g : groups) {
    const std::string name = g.tug + " / " + g.tow + " / " + g.line;
    const sweep::GridEntry* src = source_grid(sweep, g);
    if (!src) {
      plan.notes.push_back(name + ": in no grid of " + sweep.path + "; not refined");
      continue;
    }
    const std::set<double> nominal(src->speeds_kt.begin(), src->speeds_kt.end());
    if (!std::includes(nominal.begin(), nominal.end(), g.values[0].begin(), g.values[0].end())) {
      plan.notes.push_back(name + ": stored speeds are not the grid's nominal speeds (a speed reduction); not refined");
      continue;
    }
    for (RefineAxis a : options.axes) {
      const std::vector<double> v(g.values[slot(a)].begin(), g.values[slot(a)].end());
      std::size_t others = src->mean_tensions.size();
      for (RefineAxis b : kAxes) others *= b == a ? 1 : g.values[slot(b)].size();
      for (std::size_t i = 0; i + 1 < v.size(); ++i) {
        CellScore c{g.tug, g.tow, g.line, a, v[i], v[i + 1]};
        c.cases = static_cast<int>(others);
        score_cell(db, g, &c);
        plan.cells.push_back(c);
      }
    }
  }
  if (plan.cells.empty() && !groups.empty()) {
    throw InputError("refine: no group of " + db_path.string() + " is in a grid of " + sweep.path);
  }
  std::vector<std::size_t> order(plan.cells.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return plan.cells[x].score > plan.cells[y].score; });
  // Greedy: highest score first, one axis per group, within the budget.
  std::map<std::string, RefineAxis> axis_of_group;
  for (std::size_t i : order) {
    CellScore& c = plan.cells[i];
    if (!(c.score > options.threshold)) break;
    const std::string key = c.tug + "|" + c.tow + "|" + c.line;
    const auto it = axis_of_group.find(key);
    if (it != axis_of_group.end() && it->second != c.axis) continue;
    if (plan.cases + c.cases > options.max_cases) continue;
    axis_of_group.emplace(key, c.axis);
    c.chosen = true;
    plan.cases += c.cases;
  }
  // One grid per refined group, its midpoints ascending.
  for (const Group& g : groups) {
    std::vector<double> mids;
    RefineAxis axis = RefineAxis::kHeading;
    for (const CellScore& c : plan.cells) {
      if (!c.chosen || c.tug != g.tug || c.tow != g.tow || c.line != g.line) continue;
      mids.push_back(0.5 * (c.lo + c.hi));
      axis = c.axis;
    }
    if (mids.empty()) continue;
    std::sort(mids.begin(), mids.end());
    plan.grids.push_back(refinement_grid(*source_grid(sweep, g), g, axis, mids));
  }
  std::vector<CellScore> sorted;
  for (std::size_t i : order) sorted.push_back(plan.cells[i]);
  plan.cells = std::move(sorted);
  return plan;
}

std::string grids_toml(const std::vector<sweep::GridEntry>& grids) {
  std::ostringstream os;
  for (const sweep::GridEntry& e : grids) {
    os << "\n[[grid]]  # towdb refine: error-estimate-driven nodes (docs/audit.md)\n"
       << "label = \"" << e.label << "\"\n"
       << "tugs = [\"" << e.tugs.front() << "\"]\n"
       << "tows = [\"" << e.tows.front() << "\"]\n"
       << "speeds_kt = " << toml_list(e.speeds_kt) << "\n";
    std::vector<double> winds;
    for (const sweep::SeaSpec& s : e.seas) winds.push_back(*s.wind_kt);
    os << "winds_kt = " << toml_list(winds) << "\n"
       << "headings_deg = " << toml_list(e.headings_deg) << "\n"
       << "towlines = [\n";
    for (const sweep::TowlineChoice& c : e.towlines) {
      os << "  { line = \"" << model::to_string(c.line) << "\", length_ft = " << toml_number(c.length_ft) << " },\n";
    }
    os << "]\nmean_tensions = [\n";
    for (const sweep::MeanTensionLevel& l : e.mean_tensions) {
      os << "  { label = \"" << l.label << "\", basis = \""
         << (l.basis == sweep::MeanTensionBasis::kCalculated          ? "calculated"
             : l.basis == sweep::MeanTensionBasis::kHullHalfPropeller ? "hull+half-propeller"
                                                                       : "given")
         << "\", factor = " << toml_number(l.factor);
      if (l.value_lbf) os << ", value_lbf = " << toml_number(*l.value_lbf);
      os << " },\n";
    }
    os << "]\n";
    if (e.days > 0) os << "days = " << e.days << "\n";
    const sweep::MeanTensionModel& m = e.mean_model;
    os << "base_seed = " << e.base_seed << "\n"
       << "hull_margin = " << toml_number(m.hull_margin) << "\n"
       << "propeller = \"" << propeller_name(m.propeller) << "\"\n"
       << "mean_tension_wind = \"" << (m.wind == sweep::MeanTensionWind::kHead ? "head" : "heading") << "\"\n"
       << "mean_tension_limit_lbf = " << toml_number(m.limit_lbf) << "\n"
       << "speed_step_kt = " << toml_number(m.speed_step_kt) << "\n"
       << "min_speed_kt = " << toml_number(m.min_speed_kt) << "\n"
       << "sea_resistance = \"" << sea_resistance_name(m.sea_resistance) << "\"\n";
  }
  return os.str();
}

}  // namespace towdb::cli
