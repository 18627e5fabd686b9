// kill -9 in the middle of a build, then --resume: the database equals an
// uninterrupted build (generator/sweep/build/build.hpp, EQ-SWEEP-7).
// Test plan:
//   sweep-resume-1  a child process builds with a runner that sleeps per case; while it runs, a
//                   reader never sees a half-written case (every 'done' case has its results row
//                   and all its days); after some cases are committed the child gets SIGKILL;
//                   the next build refuses without --resume, then resumes, and the result rows
//                   equal a one-thread uninterrupted build bit for bit.
// This file holds one test on purpose: it forks before the process has used OpenMP.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "sweep/sweep.hpp"
#include "sweep_test_runner.hpp"
#include "test_support.hpp"

namespace towdb::test {
namespace {

namespace fs = std::filesystem;

// Cases the child must have committed before it is killed, and the runner's
// sleep: with 2 threads and 60 ms per case the 18 cases take about 0.5 s, so
// the kill lands in the middle.
constexpr std::int64_t kKillAfterDone = 5;
constexpr int kSleepPerCase_ms = 60;
constexpr auto kPollInterval = std::chrono::milliseconds(5);
constexpr auto kChildTimeout = std::chrono::seconds(60);

TEST(SweepResume, KilledBuildResumesToTheUninterruptedResult) {  // sweep-resume-1
  const fs::path dir = make_temp_dir("towdb-sweep-resume");
  const io::ShipCatalog catalog = io::ShipCatalog::load(source_dir() / "ships");
  const sweep::SweepFile file = sweep::parse_sweep(kSmallSweepToml, "small.toml");
  const std::vector<sweep::CaseSpec> cases = sweep::expand_sweep(file, catalog).cases;
  const fs::path killed = dir / "killed.db";

  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    sweep::BuildOptions o;
    o.threads = 2;
    o.progress = false;
    try {
      sweep::run_build(killed, file, cases, catalog, make_test_runner(sleeping(kSleepPerCase_ms)), o);
    } catch (...) {
      _exit(3);
    }
    _exit(0);  // finished before the kill: the parent reports it
  }

  const auto start = std::chrono::steady_clock::now();
  std::int64_t done = 0;
  int half_written = 0;
  while (done < kKillAfterDone && std::chrono::steady_clock::now() - start < kChildTimeout) {
    std::this_thread::sleep_for(kPollInterval);
    if (!fs::exists(killed)) continue;
    done = query_int(killed, "SELECT count(*) FROM cases WHERE status = 'done'");
    // A reader never sees a done case without its results and all its days.
    const std::int64_t bad = query_int(
        killed,
        "SELECT count(*) FROM cases c WHERE c.status = 'done' AND (NOT EXISTS (SELECT 1 FROM results r WHERE "
        "r.case_id = c.case_id) OR coalesce((SELECT d.days FROM case_days d WHERE d.case_id = c.case_id), 0) != c.days)");
    if (bad > 0) ++half_written;
  }
  ASSERT_EQ(kill(child, SIGKILL), 0);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the child finished before it could be killed; raise the sleep";
  EXPECT_EQ(half_written, 0);
  const std::int64_t done_at_kill = query_int(killed, "SELECT count(*) FROM cases WHERE status = 'done'");
  EXPECT_GE(done_at_kill, kKillAfterDone);
  EXPECT_LT(done_at_kill, static_cast<std::int64_t>(cases.size()));
  EXPECT_EQ(query_int(killed, "SELECT count(*) FROM builds WHERE status = 'running'"), 1);

  sweep::BuildOptions o;
  o.threads = 2;
  o.progress = false;
  EXPECT_THROW(sweep::run_build(killed, file, cases, catalog, make_test_runner(), o), InputError);
  o.resume = true;
  const sweep::BuildSummary resumed = sweep::run_build(killed, file, cases, catalog, make_test_runner(), o);
  EXPECT_EQ(resumed.up_to_date, done_at_kill);
  EXPECT_EQ(resumed.done + resumed.up_to_date, static_cast<int>(cases.size()));
  EXPECT_EQ(query_int(killed, "SELECT count(*) FROM builds WHERE status = 'interrupted'"), 1);
  EXPECT_EQ(query_int(killed, "SELECT count(*) FROM builds WHERE status = 'completed'"), 1);

  const fs::path reference = dir / "reference.db";
  sweep::BuildOptions r;
  r.threads = 1;
  r.progress = false;
  sweep::run_build(reference, file, cases, catalog, make_test_runner(), r);
  EXPECT_EQ(dump_database(killed, provenance_columns()), dump_database(reference, provenance_columns()));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace towdb::test
