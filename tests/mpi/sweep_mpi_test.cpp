// The MPI-distributed build (generator/sweep/build/distributed.hpp) under
// `mpirun -np 2`: rank 0 coordinates and writes, rank 1 computes.
// Test plan:
//   sweep-mpi-1  the database of a 2-rank build equals a single-process 1-thread build, bit for
//                bit (EQ-SWEEP-7), and its provenance row says 2 ranks
//   sweep-mpi-2  a failing case is recorded with its reason on rank 0 although rank 1 ran it
#include <filesystem>

#include <gtest/gtest.h>

#include "sweep/sweep.hpp"
#include "sweep_test_runner.hpp"
#include "test_support.hpp"

namespace towdb::test {
namespace {

namespace fs = std::filesystem;

sweep::distributed::Session* g_session = nullptr;

struct Inputs {
  io::ShipCatalog catalog = io::ShipCatalog::load(source_dir() / "ships");
  sweep::SweepFile file = sweep::parse_sweep(kSmallSweepToml, "small.toml");
  std::vector<sweep::CaseSpec> cases = sweep::expand_sweep(file, catalog).cases;
};

TEST(SweepMpi, TwoRanksEqualOneProcess) {  // sweep-mpi-1
  ASSERT_EQ(g_session->size(), 2) << "run under mpirun -np 2";
  Inputs in;
  TestRunnerOptions slow;
  slow.sleep_ms = 2;
  sweep::BuildOptions o;
  o.progress = false;
  o.session = g_session;
  if (g_session->rank() != 0) {
    const sweep::BuildSummary s = sweep::run_build("unused-on-workers.db", in.file, in.cases, in.catalog,
                                                   make_test_runner(slow), o);
    EXPECT_TRUE(s.worker);
    return;
  }
  const fs::path dir = make_temp_dir("towdb-sweep-mpi");
  const sweep::BuildSummary s =
      sweep::run_build(dir / "mpi.db", in.file, in.cases, in.catalog, make_test_runner(slow), o);
  EXPECT_FALSE(s.worker);
  EXPECT_EQ(s.done, static_cast<int>(in.cases.size()));
  sweep::BuildOptions single;
  single.progress = false;
  single.threads = 1;
  sweep::run_build(dir / "single.db", in.file, in.cases, in.catalog, make_test_runner(), single);
  EXPECT_EQ(dump_database(dir / "mpi.db", provenance_columns()),
            dump_database(dir / "single.db", provenance_columns()));
  EXPECT_EQ(query_int(dir / "mpi.db", "SELECT mpi_ranks FROM builds"), 2);
  fs::remove_all(dir);
}

TEST(SweepMpi, FailuresTravelToRankZero) {  // sweep-mpi-2
  Inputs in;
  TestRunnerOptions failing;
  failing.fail_when = [](const sweep::CaseSpec& s) { return s.sweep_label == "explicit-2"; };
  sweep::BuildOptions o;
  o.progress = false;
  o.session = g_session;
  if (g_session->rank() != 0) {
    sweep::run_build("unused-on-workers.db", in.file, in.cases, in.catalog, make_test_runner(failing), o);
    return;
  }
  const fs::path dir = make_temp_dir("towdb-sweep-mpi");
  const sweep::BuildSummary s =
      sweep::run_build(dir / "mpi.db", in.file, in.cases, in.catalog, make_test_runner(failing), o);
  EXPECT_EQ(s.failed, 1);
  EXPECT_EQ(query_int(dir / "mpi.db", "SELECT count(*) FROM cases WHERE status = 'failed' AND error_message LIKE "
                                      "'numerical error: test runner: catenary solver did not converge%'"),
            1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace towdb::test

int main(int argc, char** argv) {
  towdb::sweep::distributed::Session session;
  towdb::test::g_session = &session;
  ::testing::InitGoogleTest(&argc, argv);
  if (session.rank() != 0) {
    // Only rank 0 reports; workers still run every test body (they serve rank 0).
    delete ::testing::UnitTest::GetInstance()->listeners().Release(
        ::testing::UnitTest::GetInstance()->listeners().default_result_printer());
  }
  return RUN_ALL_TESTS();
}
