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

// Number of threads parallel_for uses for num_threads <= 0.
int max_threads();

}  // namespace towdb

#endif  // TOWDB_COMMON_PARALLEL_FOR_HPP
