// The MPI protocol of a distributed build (sweep/build/distributed.hpp carries the
// bytes): rank 0 coordinates and is the only writer; ranks 1..N-1 send
// kReady, then receive one case at a time (kWork: work index, inputs hash,
// code version, rank 0's numerics fingerprint, the case), compute it and send
// the outcome or failure back (kResult), until rank 0 sends kStop (dynamic
// scheduling). A worker whose numerics or ship files differ from rank 0's
// reports the case as an input error instead of computing it.
#ifndef TOWDB_SWEEP_BUILD_MPI_HPP
#define TOWDB_SWEEP_BUILD_MPI_HPP

#include <cstddef>
#include <functional>
#include <vector>

#include "io/ship_file.hpp"
#include "sweep/build/build.hpp"
#include "sweep/build/build_work.hpp"
#include "sweep/spec/case.hpp"
#include "sweep/spec/keys.hpp"

namespace towdb::sweep {

// Rank 0: hands out work[0..] (indices into cases) to ranks 1..ranks-1 until
// done or stopped, passing every started and finished case to `record` (the
// writer). A `record` that throws stops the dispatch; the error is rethrown
// once every worker has been sent kStop. Sets summary.interrupted when work
// was left.
void run_coordinator(const std::vector<CaseSpec>& cases, const std::vector<CaseKeys>& keys,
                     const std::vector<std::size_t>& work, const BuildOptions& options, int ranks,
                     const std::function<void(const CaseEvent&)>& record, BuildSummary& summary);

// Ranks 1..: computes the cases rank 0 sends until it sends kStop.
void run_worker(const io::ShipCatalog& catalog, const CaseRunner& runner, int rank);

// Rank 0: sends kStop to ranks 1..ranks-1 (before any work was handed out).
void stop_mpi_workers(int ranks);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_BUILD_MPI_HPP
