// Refinement driven by the error estimate (issue 16 item 1): where the query's
// own interpolation error estimate (query.h EQ-QUERY-7) is largest, add grid
// nodes, as sweep-file grids that `towdb build` computes into the database.
//
// For every (tug, tow, line) group of Pierson-Moskowitz cases, every grid axis
// a in {heading, length, wind, speed} and every cell [x_i, x_i+1] of a, the
// query is asked at the cell's midpoint with every other axis at each of its
// stored node values and the calculated mean tension (factor 1, EQ-QUERY-9):
//   score(group, a, i) = mean over those questions of
//                        interpolation_error_kips / dynamic_999_kips,
// the estimated relative error of an answer in the middle of that slab of the
// grid. A cell whose score exceeds the threshold gets a node at its midpoint:
// a hyperplane of cases (the midpoint times every stored value of the other
// axes, times the source grid's mean-tension levels), so that the group's grid
// stays complete (the query needs every corner of a cell). Cells are taken in
// descending score until the case budget is spent; at most one axis per group
// in one pass, because hyperplanes on two axes would miss their intersection.
// Running refine, then build, again refines further until no cell exceeds the
// threshold (or the budget ends it).
//
// The new grids copy the settings and mean-tension levels of the sweep's
// first grid that holds the group (so the new cases are made as the old ones
// were) and list the group's stored node values: a group whose stored speeds
// are not that grid's nominal speeds (a speed reduction) is not refined.
#ifndef TOWDB_CLI_REFINE_HPP
#define TOWDB_CLI_REFINE_HPP

#include <filesystem>
#include <string>
#include <vector>

#include "sweep/spec/sweep_file.hpp"

namespace towdb::cli {

enum class RefineAxis { kSpeed, kWind, kHeading, kLength };

const char* axis_name(RefineAxis axis);

struct RefineOptions {
  // A cell is refined when its score (estimated relative error) exceeds this.
  double threshold = 0.05;
  // New cases at most, over all refinements of this pass.
  int max_cases = 1000;
  std::vector<RefineAxis> axes = {RefineAxis::kHeading, RefineAxis::kLength, RefineAxis::kWind,
                                  RefineAxis::kSpeed};

  // Throws InputError naming the field: threshold in (0, 1), max_cases >= 1,
  // at least one axis, none twice.
  void validate() const;
};

// One cell of one group's axis, scored.
struct CellScore {
  std::string tug, tow, line;
  RefineAxis axis = RefineAxis::kHeading;
  double lo = 0.0, hi = 0.0;  // the cell; the new node is at (lo + hi) / 2
  double score = 0.0;         // mean estimated relative error at mid-cell
  int questions = 0;          // answered questions behind the score
  int cases = 0;              // cases the new node costs
  bool chosen = false;
};

struct RefinePlan {
  std::vector<CellScore> cells;        // every scored cell, highest score first
  std::vector<sweep::GridEntry> grids;  // the chosen nodes, one grid per group
  int cases = 0;                        // in `grids`
  std::vector<std::string> notes;       // groups left out and why
};

// Scores every cell and chooses the nodes. Throws InputError when the database
// or the sweep cannot be read, or when no group of the database is in the sweep.
RefinePlan plan_refinement(const std::filesystem::path& db_path, const sweep::SweepFile& sweep,
                           const RefineOptions& options);

// The chosen grids as sweep-file TOML (docs/sweep-files.md), to append to the
// sweep file they were planned from.
std::string grids_toml(const std::vector<sweep::GridEntry>& grids);

}  // namespace towdb::cli

#endif  // TOWDB_CLI_REFINE_HPP
