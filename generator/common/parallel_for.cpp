#include "common/parallel_for.hpp"

#include <exception>
#include <limits>
#include <mutex>

#include <omp.h>

namespace towdb {

int max_threads() { return omp_get_max_threads(); }

int workers(int num_threads) { return num_threads > 0 ? num_threads : omp_get_max_threads(); }

void parallel_for_workers(std::int64_t begin, std::int64_t end, int num_threads,
                          const std::function<void(std::int64_t, int)>& fn) {
  if (end <= begin) return;
  const int threads = workers(num_threads);
  if (threads == 1 || end - begin == 1) {
    for (std::int64_t i = begin; i < end; ++i) fn(i, 0);
    return;
  }
  std::mutex mutex;
  std::exception_ptr first_error;
  std::int64_t first_error_index = std::numeric_limits<std::int64_t>::max();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t i = begin; i < end; ++i) {
    try {
      fn(i, omp_get_thread_num());
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (i < first_error_index) {
        first_error_index = i;
        first_error = std::current_exception();
      }
    }
  }
  if (first_error) std::rethrow_exception(first_error);
}

void parallel_for(std::int64_t begin, std::int64_t end, int num_threads,
                  const std::function<void(std::int64_t)>& fn) {
  parallel_for_workers(begin, end, num_threads, [&fn](std::int64_t i, int) { fn(i); });
}

}  // namespace towdb
