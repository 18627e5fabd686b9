// What a build's workers hand to its one writer: the event of one case
// starting or finishing, and the worker's side of computing one case. Shared
// by the threaded build (sweep/build/build.cpp) and the MPI one (sweep/build/build_mpi.hpp).
#ifndef TOWDB_SWEEP_BUILD_WORK_HPP
#define TOWDB_SWEEP_BUILD_WORK_HPP

#include <cstddef>
#include <string>

#include "io/ship_file.hpp"
#include "sweep/build/build.hpp"
#include "sweep/spec/case.hpp"

namespace towdb::sweep {

// One case started or computed, handed from a worker to the writer.
struct CaseEvent {
  enum class Kind { kStarted, kFinished };
  Kind kind = Kind::kFinished;
  std::size_t work = 0;  // index into the work list
  bool ok = false;
  CaseOutcome outcome;
  std::string error;
  double runtime_s = 0.0;
};

// Runs the runner on one case and never throws: a failure becomes the
// event's error text, prefixed by its kind.
CaseEvent run_one(std::size_t work, const CaseSpec& spec, const io::ShipCatalog& catalog, const CaseRunner& runner);

// Whether the build was asked to stop (BuildOptions::stop): no new case starts.
inline bool stop_requested(const BuildOptions& o) { return o.stop && o.stop->load(); }

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_BUILD_WORK_HPP
