#include "sweep/build/build.hpp"

#include <cstdio>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <unordered_map>
#include <system_error>
#include <utility>

#include <unistd.h>

#include "common/error.hpp"
#include "common/parallel_for.hpp"
#include "store/database.hpp"
#include "store/key_bytes.hpp"
#include "sweep/build/build_lock.hpp"
#include "sweep/build/build_mpi.hpp"
#include "sweep/build/build_work.hpp"
#include "sweep/build/numerics.hpp"
#include "sweep/build/progress.hpp"

namespace towdb::sweep {

namespace {

constexpr int kMaxThreads = 1024;

// Worker threads push, the one writer thread pops.
class EventQueue {
 public:
  void push(CaseEvent e) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      events_.push_back(std::move(e));
    }
    ready_.notify_one();
  }
  void close() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      closed_ = true;
    }
    ready_.notify_all();
  }
  // False when closed and empty.
  bool pop(CaseEvent* out) {
    std::unique_lock<std::mutex> lock(mutex_);
    ready_.wait(lock, [&] { return closed_ || !events_.empty(); });
    if (events_.empty()) return false;
    *out = std::move(events_.front());
    events_.pop_front();
    return true;
  }

 private:
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<CaseEvent> events_;
  bool closed_ = false;
};

std::string host_name() {
  char buffer[256] = {};
  if (::gethostname(buffer, sizeof buffer - 1) != 0) return "unknown";
  return buffer;
}

// Applies events to the database (the writer's side) and keeps the counts.
class Recorder {
 public:
  Recorder(DatabaseWriter& writer, const std::vector<CaseSpec>& cases, const std::vector<CaseKeys>& keys,
           const std::vector<std::size_t>& work, const std::vector<RegisteredCase>& registered,
           const BuildOptions& options, std::int64_t build_id, BuildSummary& summary)
      : writer_(writer),
        cases_(cases),
        keys_(keys),
        work_(work),
        registered_(registered),
        options_(options),
        build_id_(build_id),
        summary_(summary),
        progress_(static_cast<int>(work.size()), options.progress) {}

  void apply(const CaseEvent& e) {
    const std::size_t i = work_[e.work];
    const std::int64_t case_id = registered_[i].case_id;
    if (e.kind == CaseEvent::Kind::kStarted) {
      writer_.mark_running(case_id, build_id_);
      return;
    }
    if (e.ok) {
      writer_.write_result(case_id, cases_[i], keys_[i], e.outcome, e.runtime_s, options_.code_version, build_id_);
      ++summary_.done;
    } else {
      writer_.write_failure(case_id, e.error, build_id_);
      ++summary_.failed;
      summary_.failures.push_back("case_id " + std::to_string(case_id) + " (" + cases_[i].sweep_label + ", " +
                                  cases_[i].tug + " / " + cases_[i].tow + "): " + e.error);
    }
    progress_.update(summary_.done, summary_.failed);
  }

  void finish() { progress_.finish(summary_.done, summary_.failed); }

 private:
  DatabaseWriter& writer_;
  const std::vector<CaseSpec>& cases_;
  const std::vector<CaseKeys>& keys_;
  const std::vector<std::size_t>& work_;
  const std::vector<RegisteredCase>& registered_;
  const BuildOptions& options_;
  std::int64_t build_id_;
  BuildSummary& summary_;
  ProgressBar progress_;
};

// ---------------------------------------------------------------------------
// One process: OpenMP workers, one writer thread.
void run_threads(const std::vector<CaseSpec>& cases, const std::vector<std::size_t>& work,
                 const io::ShipCatalog& catalog, const CaseRunner& runner, const BuildOptions& options,
                 Recorder& recorder, BuildSummary& summary) {
  EventQueue queue;
  std::atomic<bool> writer_failed{false};
  std::exception_ptr writer_error;
  std::thread writer([&] {
    CaseEvent e;
    while (queue.pop(&e)) {
      if (writer_failed.load()) continue;  // drain without writing
      try {
        recorder.apply(e);
      } catch (...) {
        writer_error = std::current_exception();
        writer_failed.store(true);
      }
    }
  });
  std::atomic<int> skipped{0};
  parallel_for(0, static_cast<std::int64_t>(work.size()), options.threads, [&](std::int64_t w) {
    const auto wi = static_cast<std::size_t>(w);
    if (stop_requested(options) || writer_failed.load()) {
      ++skipped;
      return;
    }
    CaseEvent started;
    started.kind = CaseEvent::Kind::kStarted;
    started.work = wi;
    queue.push(std::move(started));
    queue.push(run_one(wi, cases[work[wi]], catalog, runner));
  });
  queue.close();
  writer.join();
  if (writer_error) std::rethrow_exception(writer_error);
  summary.interrupted = skipped.load() > 0;
}

// The key of meta that holds the numerics fingerprint of the processes that
// computed the database's cases (numerics.hpp).
constexpr const char* kNumericsKey = "numerics_fingerprint";

// An existing, current towdb database opened read-only; none for a missing or
// empty file, or one that is not readable as a current towdb database (an
// older schema, or not a towdb file: the writable open that a build makes
// next migrates it or says why).
std::optional<store::Database> open_for_checks(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec) || std::filesystem::file_size(path, ec) == 0 || ec) return {};
  try {
    return store::Database::open(path, store::Database::Mode::kReadOnly);
  } catch (const InputError&) {
    return {};
  }
}

std::optional<std::string> recorded_numerics(store::Database& db) {
  store::Statement st = db.prepare("SELECT value FROM meta WHERE key = ?");
  st.bind(1, kNumericsKey);
  if (!st.step()) return {};
  return st.column_text(0);
}

std::string unfinished_build_refusal(const std::filesystem::path& path, std::int64_t build_id) {
  return path.string() + ": build " + std::to_string(build_id) +
         " did not finish (killed or crashed); run again with --resume to continue it (done cases "
         "are kept, unfinished ones are recomputed)";
}

// The refusals that need the database's contents, made through a read-only
// connection before the writable open (which would already switch a
// DELETE-journal file, such as the bundled database, to WAL):
//   - an unfinished build without --resume;
//   - one database, one numerics fingerprint: a build that would compute a
//     case on a machine whose fingerprint differs from the one the database
//     records (its results would differ in the last bits from what the first
//     machine computes). A build with nothing to compute is not refused.
//     Databases written before version 0.2.0 record none.
void check_before_writing(const std::filesystem::path& path, const std::vector<CaseSpec>& cases,
                          const std::vector<CaseKeys>& keys, const io::ShipCatalog& catalog,
                          const BuildOptions& options, const std::string& fingerprint) {
  const bool resume = options.resume, retry_failed = options.retry_failed;
  std::optional<store::Database> opened = open_for_checks(path);
  if (!opened) return;
  store::Database& db = *opened;
  if (!resume) {
    store::Statement running = db.prepare("SELECT max(build_id) FROM builds WHERE status = 'running'");
    if (running.step() && !running.is_null(0)) {
      throw InputError(unfinished_build_refusal(path, running.column_int(0)));
    }
  }
  const std::optional<std::string> recorded = recorded_numerics(db);
  if (!recorded || *recorded == fingerprint) return;
  const std::string& stored = *recorded;
  store::Statement by_key = db.prepare("SELECT status FROM cases WHERE case_key = ?");
  EarlierShipFiles earlier(db, catalog, options.code_version);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    by_key.bind_blob(1, store::key_bytes(keys[i].case_key, "case_key"));
    CaseState state = CaseState::kNew;
    if (by_key.step()) {
      state = state_of_stored(by_key.column_text(0));
    } else if (const std::optional<StoredCase> same = earlier.stored_case(cases[i])) {
      state = state_of_stored(same->status);  // re-keyed, not recomputed
    }
    by_key.reset();
    if (!computes(state, retry_failed)) continue;
    throw InputError(path.string() + ": meta." + kNumericsKey + " = " + stored +
                     ", but this machine computes with numerics fingerprint " + fingerprint +
                     " (towdb --version; another FFT plan or math library): its cases would differ in the last "
                     "bits from the database's. Build on a machine kind with " + stored +
                     ", or into a new database");
  }
}

}  // namespace

std::optional<std::string> recorded_numerics_fingerprint(const std::filesystem::path& db_path) {
  std::optional<store::Database> db = open_for_checks(db_path);
  if (!db) return {};
  return recorded_numerics(*db);
}

void BuildOptions::validate() const {
  require_input(threads >= 1 && threads <= kMaxThreads, "BuildOptions.threads", threads,
                "must be a whole number in [1, 1024]");
  require_input(!code_version.empty(), "BuildOptions.code_version", 0.0, "must not be empty");
}

std::vector<CaseKeys> compute_keys(const std::vector<CaseSpec>& cases, const io::ShipCatalog& catalog,
                                   const std::string& code_version) {
  std::vector<CaseKeys> keys;
  keys.reserve(cases.size());
  for (const CaseSpec& s : cases) {
    s.validate();
    keys.push_back(case_keys(s, catalog, code_version));
  }
  return keys;
}

std::vector<PlannedCase> plan_build(const std::optional<std::filesystem::path>& db_path,
                                    const std::vector<CaseSpec>& cases, const io::ShipCatalog& catalog,
                                    const std::string& code_version) {
  const std::vector<CaseKeys> keys = compute_keys(cases, catalog, code_version);
  std::vector<PlannedCase> plan(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) plan[i] = {cases[i], keys[i], CaseState::kNew};
  if (!db_path || !std::filesystem::exists(*db_path)) return plan;
  store::Database db = store::Database::open(*db_path, store::Database::Mode::kReadOnly);
  store::Statement by_key = db.prepare("SELECT status FROM cases WHERE case_key = ?");
  store::Statement by_condition = db.prepare("SELECT 1 FROM cases WHERE condition_key = ?");
  EarlierShipFiles earlier(db, catalog, code_version);
  for (PlannedCase& p : plan) {
    by_key.bind_blob(1, store::key_bytes(p.keys.case_key, "case_key"));
    if (by_key.step()) {
      p.state = state_of_stored(by_key.column_text(0));
    } else if (const std::optional<StoredCase> stored = earlier.stored_case(p.spec)) {
      p.state = state_of_stored(stored->status);
      p.rekey = true;
    } else {
      by_condition.bind_blob(1, store::key_bytes(p.spec.condition_key, "condition_key"));
      if (by_condition.step()) p.state = CaseState::kChanged;
      by_condition.reset();
    }
    by_key.reset();
  }
  return plan;
}

namespace {

// Fits stored before schema 6 get their lowest point from an up-to-date case
// of this sweep that uses them (its key, hence the fit's inputs, unchanged).
int fill_lowest_points(DatabaseWriter& writer, const std::vector<CaseSpec>& cases, const std::vector<CaseKeys>& keys,
                       const std::vector<RegisteredCase>& registered, const io::ShipCatalog& catalog,
                       const LowestPointFn& lowest_elevation_m) {
  if (!lowest_elevation_m) return 0;
  const std::vector<FitWithoutLowestPoint> missing = writer.fits_without_lowest_point();
  if (missing.empty()) return 0;
  std::unordered_map<std::int64_t, std::size_t> done_by_case_id;
  for (std::size_t i = 0; i < registered.size(); ++i) {
    if (registered[i].state == CaseState::kDone) done_by_case_id.emplace(registered[i].case_id, i);
  }
  std::vector<std::pair<std::int64_t, double>> filled;
  for (const FitWithoutLowestPoint& m : missing) {
    if (!filled.empty() && filled.back().first == m.fit_id) continue;
    const auto it = done_by_case_id.find(m.case_id);
    if (it == done_by_case_id.end() || keys[it->second].fit_id != m.fit_id) continue;
    filled.emplace_back(m.fit_id, lowest_elevation_m(cases[it->second], catalog));
  }
  writer.set_lowest_points(filled);
  return static_cast<int>(filled.size());
}

}  // namespace

BuildSummary run_build(const std::filesystem::path& db_path, const SweepFile& sweep,
                       const std::vector<CaseSpec>& cases, const io::ShipCatalog& catalog, const CaseRunner& runner,
                       const BuildOptions& options) {
  options.validate();
  if (!runner) throw InputError("build: no case runner was given");
  BuildSummary summary;
  const int ranks = options.session ? options.session->size() : 1;
  const int rank = options.session ? options.session->rank() : 0;
  if (rank != 0) {
    summary.worker = true;
    try {
      run_worker(catalog, runner, rank);
    } catch (const std::exception& e) {
      // Rank 0 would wait for this rank forever: end every rank.
      std::fprintf(stderr, "towdb: MPI rank %d: %s\n", rank, e.what());
      distributed::abort_all(1);
    }
    return summary;
  }

  // Everything that can be checked without the database first.
  std::vector<CaseKeys> keys;
  auto stop_workers = [ranks] { stop_mpi_workers(ranks); };
  try {
    keys = compute_keys(cases, catalog, options.code_version);
    require_writable(db_path);
  } catch (...) {
    stop_workers();
    throw;
  }

  std::optional<BuildLock> lock;
  std::optional<store::Database> db;
  std::optional<DatabaseWriter> writer;
  std::vector<RegisteredCase> registered;
  std::vector<std::size_t> work;
  try {
    lock.emplace(db_path);
    check_before_writing(db_path, cases, keys, catalog, options, numerics_fingerprint());
    db.emplace(store::Database::open(db_path, store::Database::Mode::kCreate));
    writer.emplace(*db);
    const std::vector<std::int64_t> unfinished = writer->unfinished_builds();
    if (!unfinished.empty()) {
      if (!options.resume) {
        throw InputError(unfinished_build_refusal(db_path, unfinished.back()));
      }
      writer->mark_interrupted(unfinished);
    }
    BuildProvenance p;
    p.code_version = options.code_version;
    p.command_line = options.command_line;
    p.sweep_file = sweep.path;
    p.sweep_sha256 = sweep.sha256;
    p.host = host_name();
    p.threads = options.threads;
    p.mpi_ranks = ranks;
    summary.build_id = writer->begin_build(p);
    writer->record_coverage(summary.build_id, sweep.path, options.coverage_notes, options.skipped);
    store::Statement record = db->prepare("INSERT OR IGNORE INTO meta (key, value) VALUES (?, ?)");
    record.bind(1, kNumericsKey).bind(2, numerics_fingerprint()).run();
  } catch (...) {
    stop_workers();
    throw;
  }

  try {
    EarlierShipFiles earlier(*db, catalog, options.code_version);
    registered = writer->register_cases(cases, keys, catalog, summary.build_id, options.retry_failed, &earlier);
    for (const RegisteredCase& r : registered) summary.rekeyed += r.rekeyed ? 1 : 0;
    summary.lowest_points_filled =
        fill_lowest_points(*writer, cases, keys, registered, catalog, options.lowest_elevation_m);
    writer->set_day_records(sweep.day_records);
    if (sweep.day_records == DayRecords::kMaxima) summary.slack_snatch_dropped = writer->drop_slack_snatch_days();
    writer->set_maxima_precision(sweep.maxima_precision);
    if (sweep.maxima_precision == MaximaPrecision::kBinary16) summary.maxima_repacked = writer->pack_maxima_binary16();
    summary.total = static_cast<int>(cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const CaseState state = registered[i].state;
      if (computes(state, options.retry_failed)) {
        work.push_back(i);
      } else if (state == CaseState::kDone) {
        ++summary.up_to_date;
      } else {
        ++summary.previously_failed;
      }
    }
    summary.scheduled = static_cast<int>(work.size());
    Recorder recorder(*writer, cases, keys, work, registered, options, summary.build_id, summary);
    if (ranks > 1) {
      run_coordinator(cases, keys, work, options, ranks, [&recorder](const CaseEvent& e) { recorder.apply(e); },
                      summary);
    } else {
      run_threads(cases, work, catalog, runner, options, recorder, summary);
    }
    recorder.finish();
    if (!summary.interrupted && options.heading_profile) {
      summary.profiles = update_heading_profiles(*db, cases, keys, catalog, options.heading_profile, options.threads,
                                                 summary.build_id, options.stop);
      summary.interrupted = summary.profiles.interrupted;
    }
    if (!summary.interrupted && options.speed_profile) {
      summary.speed_profiles = update_speed_profiles(*db, cases, keys, catalog, options.speed_profile,
                                                     options.threads, summary.build_id, options.stop);
      summary.interrupted = summary.speed_profiles.interrupted;
    }
  } catch (...) {
    if (ranks > 1 && registered.empty()) stop_workers();
    try {
      writer->finish_build(summary.build_id, "failed", summary.done, summary.failed);
    } catch (...) {
      // The original error matters more than a failed status update.
    }
    throw;
  }
  writer->finish_build(summary.build_id, summary.interrupted ? "interrupted" : "completed", summary.done,
                       summary.failed);
  return summary;
}

}  // namespace towdb::sweep
