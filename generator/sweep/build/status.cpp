#include "sweep/build/status.hpp"

#include "store/database.hpp"

namespace towdb::sweep {

StatusReport read_status(const std::filesystem::path& db_path, int max_builds, int max_failed) {
  store::Database db = store::Database::open(db_path, store::Database::Mode::kReadOnly);
  StatusReport r;
  r.schema_version = db.schema_version();
  auto count = [&](const char* sql) {
    store::Statement st = db.prepare(sql);
    st.step();
    return st.column_int(0);
  };
  r.cases = count("SELECT count(*) FROM cases");
  r.results = count("SELECT count(*) FROM results");
  r.daily_maxima = count("SELECT coalesce(sum(days), 0) FROM case_days");
  r.towline_fits = count("SELECT count(*) FROM towline_fits");
  r.heading_profiles = count("SELECT count(*) FROM heading_profiles");
  r.cases_with_profile = count("SELECT count(*) FROM cases WHERE profile_id IS NOT NULL");
  r.speed_profiles = count("SELECT count(*) FROM speed_profiles");
  r.cases_with_speed_profile = count("SELECT count(*) FROM cases WHERE speed_profile_id IS NOT NULL");
  r.vessels = count("SELECT count(*) FROM vessels");
  for (const char* s : {"pending", "running", "done", "failed"}) r.cases_by_status[s] = 0;
  {
    store::Statement st = db.prepare("SELECT status, count(*) FROM cases GROUP BY status");
    while (st.step()) r.cases_by_status[st.column_text(0)] = st.column_int(1);
  }
  {
    store::Statement st = db.prepare("SELECT sweep_label, count(*) FROM cases GROUP BY sweep_label");
    while (st.step()) r.cases_by_sweep_label[st.column_text(0)] = st.column_int(1);
  }
  {
    store::Statement st = db.prepare("SELECT sum(runtime_s) FROM results");
    st.step();
    r.total_runtime_s = st.column_optional_double(0);
  }
  {
    store::Statement st = db.prepare(
        "SELECT build_id, code_version, sweep_file, host, threads, mpi_ranks, started_utc, finished_utc, status, "
        "cases_done, cases_failed FROM builds ORDER BY build_id DESC LIMIT ?");
    st.bind(1, max_builds);
    while (st.step()) {
      BuildRecord b;
      b.build_id = st.column_int(0);
      b.code_version = st.column_text(1);
      b.sweep_file = st.column_text(2);
      b.host = st.column_text(3);
      b.threads = static_cast<int>(st.column_int(4));
      b.mpi_ranks = static_cast<int>(st.column_int(5));
      b.started_utc = st.column_text(6);
      b.finished_utc = st.column_text(7);
      b.status = st.column_text(8);
      b.cases_done = static_cast<int>(st.column_int(9));
      b.cases_failed = static_cast<int>(st.column_int(10));
      r.builds.push_back(b);
    }
  }
  {
    store::Statement st = db.prepare(
        "SELECT case_id, sweep_label, tug_name, tow_name, coalesce(error_message, '') FROM cases "
        "WHERE status = 'failed' ORDER BY case_id LIMIT ?");
    st.bind(1, max_failed);
    while (st.step()) {
      r.failed.push_back({st.column_int(0), st.column_text(1), st.column_text(2), st.column_text(3),
                          st.column_text(4)});
    }
  }
  {
    // cases.build_id is rewritten only when a build changes the case's status (writer.cpp).
    store::Statement st = db.prepare(
        "SELECT max(b) FROM (SELECT max(build_id) AS b FROM cases WHERE status = 'done' "
        "UNION ALL SELECT max(build_id) FROM heading_profiles UNION ALL SELECT max(build_id) FROM speed_profiles)");
    st.step();
    if (!st.is_null(0)) r.content_build_id = st.column_int(0);
  }
  {
    store::Statement st = db.prepare("SELECT value FROM meta WHERE key = 'last_audit'");
    if (st.step()) r.last_audit = st.column_text(0);
  }
  return r;
}

}  // namespace towdb::sweep
