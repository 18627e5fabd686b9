// towdb refine: where the query's interpolation error estimate is largest,
// new grid nodes as sweep-file grids (refine.hpp; issue 16 item 1).
//
//   towdb refine --db F --sweep S [--threshold 0.05] [--max-cases 1000]
//                [--axes heading,length,wind,speed] [--append | --toml] [--json]
//
// Prints the scored cells and the chosen nodes. --toml prints only the new
// grids; --append adds them to S (written whole to a temporary file, then
// renamed: S is never half-written), after which `towdb build --sweep S --db F`
// computes the new cases. Nothing is appended when no cell exceeds the
// threshold (exit 0, "nothing to refine").
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "common/error.hpp"
#include "output.hpp"
#include "refine.hpp"

namespace towdb::cli {

namespace {

struct RefineArgs {
  std::string db, sweep;
  RefineOptions options;
  std::vector<std::string> axes = {"heading", "length", "wind", "speed"};
  bool append = false, toml = false, json = false;
};

RefineAxis parse_axis(const std::string& name) {
  for (RefineAxis a : {RefineAxis::kSpeed, RefineAxis::kWind, RefineAxis::kHeading, RefineAxis::kLength}) {
    if (name == axis_name(a)) return a;
  }
  throw InputError("refine: --axes: \"" + name + "\" is not an axis; allowed: speed, wind, heading, length");
}

std::string cell_text(const CellScore& c) {
  const char* unit = c.axis == RefineAxis::kHeading ? " deg" : c.axis == RefineAxis::kLength ? " ft" : " kt";
  return fmt(c.lo) + "-" + fmt(c.hi) + unit;
}

void print_text(const RefinePlan& plan, const RefineArgs& a) {
  TextTable t({"tug", "tow", "line", "axis", "cell", "new node", "score %", "questions", "cases", "chosen"});
  int shown = 0;
  for (const CellScore& c : plan.cells) {
    if (!c.chosen && shown >= 20) continue;
    ++shown;
    t.add_row({c.tug, c.tow, c.line, axis_name(c.axis), cell_text(c), fmt(0.5 * (c.lo + c.hi)),
               fmt(100.0 * c.score, 1), std::to_string(c.questions), std::to_string(c.cases), c.chosen ? "yes" : ""});
  }
  std::cout << "cells scored by the estimated relative error at mid-cell (EQ-QUERY-7), highest first"
            << " (threshold " << fmt(100.0 * a.options.threshold, 1) << " %):\n";
  t.print(std::cout);
  for (const std::string& n : plan.notes) std::cout << "note: " << n << "\n";
  if (plan.grids.empty()) {
    std::cout << "nothing to refine: no cell above the threshold within the budget\n";
    return;
  }
  std::cout << plan.grids.size() << " groups refined, " << plan.cases << " new cases";
  if (a.append) {
    std::cout << "; appended to " << a.sweep << ": run towdb build --sweep " << a.sweep << " --db " << a.db;
  } else {
    std::cout << " (--append adds them to " << a.sweep << ")";
  }
  std::cout << "\n";
}

nlohmann::ordered_json plan_json(const RefinePlan& plan, const RefineArgs& a) {
  nlohmann::ordered_json cells = nlohmann::ordered_json::array();
  for (const CellScore& c : plan.cells) {
    cells.push_back({{"tug", c.tug},
                     {"tow", c.tow},
                     {"line", c.line},
                     {"axis", axis_name(c.axis)},
                     {"low", c.lo},
                     {"high", c.hi},
                     {"new_node", 0.5 * (c.lo + c.hi)},
                     {"score", c.score},
                     {"questions", c.questions},
                     {"cases", c.cases},
                     {"chosen", c.chosen}});
  }
  return {{"threshold", a.options.threshold}, {"max_cases", a.options.max_cases},
          {"new_cases", plan.cases},          {"appended", a.append && !plan.grids.empty()},
          {"notes", plan.notes},              {"cells", cells},
          {"toml", grids_toml(plan.grids)}};
}

// Writes `text` to `path` through a temporary file in the same directory.
void replace_file(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path tmp = path.string() + ".refine-tmp";
  {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    f.flush();
    if (!f) throw StorageError("refine: cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path);
}

int run_refine(const RefineArgs& in) {
  RefineArgs a = in;
  if (a.append && a.toml) throw InputError("refine: --append and --toml: give one of them");
  a.options.axes.clear();
  for (const std::string& name : a.axes) a.options.axes.push_back(parse_axis(name));
  a.options.validate();
  const sweep::SweepFile sweep = sweep::load_sweep(a.sweep);
  const RefinePlan plan = plan_refinement(a.db, sweep, a.options);
  const std::string toml = grids_toml(plan.grids);
  if (a.append && !plan.grids.empty()) {
    std::ifstream f(a.sweep, std::ios::binary);
    std::stringstream text;
    text << f.rdbuf();
    const std::string updated = text.str() + toml;
    sweep::parse_sweep(updated, a.sweep);  // the file must stay valid: checked before it is replaced
    replace_file(a.sweep, updated);
  }
  if (a.toml) {
    std::cout << toml;
  } else if (a.json) {
    std::cout << plan_json(plan, a).dump(2) << "\n";
  } else {
    print_text(plan, a);
  }
  return 0;
}

}  // namespace

void add_refine_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<RefineArgs>();
  CLI::App* cmd = app.add_subcommand(
      "refine", "Add grid nodes where the estimated interpolation error is largest, as sweep-file grids");
  cmd->add_option("--db", args->db, "towdb database file (opened read-only)")->required();
  cmd->add_option("--sweep", args->sweep, "The sweep file the database was built from")->required();
  cmd->add_option("--threshold", args->options.threshold,
                  "Refine cells whose estimated relative error at mid-cell exceeds this fraction (default 0.05)")
      ->check(number_in(0.0, 1.0, true, true));
  cmd->add_option("--max-cases", args->options.max_cases, "New cases at most in this pass (default 1000)")
      ->check(CLI::Range(1, 10000000));
  cmd->add_option("--axes", args->axes, "Axes to refine (default heading,length,wind,speed)")->delimiter(',');
  cmd->add_flag("--append", args->append, "Append the new grids to the sweep file");
  cmd->add_flag("--toml", args->toml, "Print only the new grids (sweep-file TOML)");
  cmd->add_flag("--json", args->json, "JSON output");
  cmd->callback([&ctx, args] { ctx.action = [args] { return run_refine(*args); }; });
}

}  // namespace towdb::cli
