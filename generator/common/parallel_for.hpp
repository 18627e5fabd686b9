// The one place towdb uses OpenMP (after Ceres internal/ceres/parallel_for.h).
//
// parallel_for(begin, end, num_threads, fn) calls fn(i) for every i in
// [begin, end), spread over num_threads threads with dynamic scheduling.
// fn must write only to per-index outputs: results are then bit-identical for
// any thread count, because every index is computed by the same code on the
// same inputs regardless of which thread runs it. num_threads <= 0 means "all
// available". Exceptions thrown by fn are caught and the first one (by lowest
// index) is rethrown after the loop, so error reporting is deterministic too.
#ifndef TOWDB_COMMON_PARALLEL_FOR_HPP
#define TOWDB_COMMON_PARALLEL_FOR_HPP

#include <cstdint>
#include <functional>

namespace towdb {

void parallel_for(std::int64_t begin, std::int64_t end, int num_threads,
                  const std::function<void(std::int64_t)>& fn);

// The same, also passing the worker number w in [0, workers(num_threads)), so
// that fn can reuse per-worker scratch storage (results must still not
// depend on which worker ran an index).
void parallel_for_workers(std::int64_t begin, std::int64_t end, int num_threads,
                          const std::function<void(std::int64_t index, int worker)>& fn);

// Number of workers parallel_for uses for num_threads (<= 0: all available).
int workers(int num_threads);

// Number of threads parallel_for uses for num_threads <= 0.
int max_threads();

}  // namespace towdb

#endif  // TOWDB_COMMON_PARALLEL_FOR_HPP
