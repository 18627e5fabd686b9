#include "sweep/build/profile_stage.hpp"

#include <algorithm>
#include <exception>

#include "common/parallel_for.hpp"

namespace towdb::sweep {

void point_cases_at(store::Database& db, const char* column, const std::vector<std::int64_t>& case_ids,
                    std::int64_t profile_id) {
  const std::string c(column);
  store::Statement st = db.prepare("UPDATE cases SET " + c + " = ? WHERE case_id = ? AND " + c + " IS NOT ?");
  for (std::int64_t id : case_ids) {
    st.reset();
    if (profile_id == 0) {
      st.bind_null(1).bind(2, id).bind_null(3);
    } else {
      st.bind(1, profile_id).bind(2, id).bind(3, profile_id);
    }
    st.run();
  }
}

void run_stage_chunks(store::Database& db, const StageWork& work, int threads, const std::atomic<bool>* stop,
                      ProfileSummary& summary) {
  constexpr std::size_t kChunk = 32;
  for (std::size_t begin = 0; begin < work.count; begin += kChunk) {
    if (stop && stop->load()) {
      summary.interrupted = true;
      break;
    }
    const std::size_t end = std::min(work.count, begin + kChunk);
    std::vector<std::string> blob(end - begin), failure(end - begin);
    parallel_for(static_cast<std::int64_t>(begin), static_cast<std::int64_t>(end), threads, [&](std::int64_t w) {
      const auto k = static_cast<std::size_t>(w) - begin;
      try {
        blob[k] = work.compute(static_cast<std::size_t>(w));
      } catch (const std::exception& e) {
        failure[k] = *e.what() ? e.what() : "unknown error";
      }
    });
    for (std::size_t w = begin; w < end; ++w) {
      const std::size_t k = w - begin;
      if (!failure[k].empty()) {
        ++summary.failed;
        summary.failures.push_back(work.name(w) + ": " + failure[k]);
        db.transaction([&] { work.clear(w); });
        continue;
      }
      db.transaction([&] { work.write(w, blob[k]); });
      ++summary.computed;
    }
  }
  std::sort(summary.failures.begin(), summary.failures.end());
}

}  // namespace towdb::sweep
