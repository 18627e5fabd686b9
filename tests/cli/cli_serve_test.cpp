// Tests of `towdb serve` (issue 18 item 3) through its HTTP API on loopback,
// against the bundled database.
// Test plan:
//   cli-serve-1  binds 127.0.0.1 (the printed URL); / is the planner form; /chart.js is
//                Debian's Chart.js; /api/vessels lists the stored combinations
//   cli-serve-2  /api/query answers as `towdb query --json` (same library: exact);
//                /api/plan's chosen answer is the same; POST one question or a list
//   cli-serve-3  bad requests: 400 with the field named (not a number, outside the
//                stored data, unknown vessel, unknown field, missing field, bad JSON,
//                more than 100 questions); a body over 64 KiB is 413, a URI over 8 KiB 414
//   cli-serve-4  the rate limit: past the burst a client gets 429 with Retry-After
//   cli-serve-5  the database is opened read-only: a read-only file is served and left
//                byte for byte as it was
//   cli-serve-6  load: 2,000 requests from 8 clients on loopback, no error, every answer
//                the expected one; latency percentiles printed (docs/performance.md)
//   cli-serve-7  bad flags exit 2 naming the flag: --port 70000, a missing database, a
//                --bind address no interface of this machine has
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include "serve_process.hpp"
#include "test_support.hpp"

extern char** environ;

namespace towdb::test {
namespace {

using nlohmann::json;

const std::string kReadmeQuery =
    "tug=T-ATF&tow=FFG7&line=fiber&speed_kt=7&wind_kt=30&heading_deg=150&length_ft=1200";

json get_json(httplib::Client& c, const std::string& path, int expected_status) {
  const auto r = c.Get(path.c_str());
  EXPECT_TRUE(r) << path;
  if (!r) return json();
  EXPECT_EQ(r->status, expected_status) << path << "\n" << r->body;
  return json::parse(r->body);
}

class CliServe : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { server_ = new ServerProcess({"--db", "db/towdb.sqlite", "--rate-limit-per-s", "1e5"}); }
  static void TearDownTestSuite() {
    EXPECT_EQ(server_->stop(), 0);
    delete server_;
  }
  static ServerProcess* server_;
};
ServerProcess* CliServe::server_ = nullptr;

TEST_F(CliServe, ServesThePageAndChartJsOnLoopback) {  // cli-serve-1
  EXPECT_NE(server_->first_line().find("http://127.0.0.1:"), std::string::npos);
  auto c = server_->client();
  const auto page = c.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  for (const char* id : {"id=\"question\"", "id=\"tug\"", "id=\"chart-speed\"", "src=\"/chart.js\""}) {
    EXPECT_NE(page->body.find(id), std::string::npos) << id;
  }
  const auto chart = c.Get("/chart.js");
  ASSERT_TRUE(chart);
  EXPECT_NE(chart->body.find("Chart.js v"), std::string::npos);
  const json v = get_json(c, "/api/vessels", 200);
  ASSERT_EQ(v.at("combinations").size(), 20u);  // 2 tugs x 5 tows x 2 lines (db/README.md)
  EXPECT_EQ(v.at("combinations")[0].at("tug"), "ARS 50");
}

TEST_F(CliServe, AnswersAsTheCli) {  // cli-serve-2
  auto c = server_->client();
  const json a = get_json(c, "/api/query?" + kReadmeQuery, 200);
  const CommandResult cli = run_towdb(
      "query --db db/towdb.sqlite --tug T-ATF --tow FFG7 --line fiber --speed-kt 7 --wind-kt 30 --heading-deg 150 "
      "--length-ft 1200 --json");
  ASSERT_EQ(cli.exit_code, 0) << cli.err;
  json expected = json::parse(cli.out);
  expected.erase("mean_tension_default");  // the CLI's note on where the default came from
  EXPECT_EQ(a, expected);
  const json plan = get_json(c, "/api/plan?" + kReadmeQuery + "&curve_headings_deg=0,90", 200);
  EXPECT_EQ(plan.at("answer").at("extreme_tension_lbf"), expected.at("extreme_tension_lbf"));
  EXPECT_EQ(plan.at("tension_vs_speed").size(), 2u);
  const auto post = c.Post("/api/query", R"([{"tug":"T-ATF","tow":"FFG7","line":"fiber","speed_kt":7,"wind_kt":30,
      "heading_deg":150,"length_ft":1200},{"tug":"T-ATF","tow":"FFG7","line":"fiber","speed_kt":30,"wind_kt":30,
      "heading_deg":150,"length_ft":1200}])",
                           "application/json");
  ASSERT_TRUE(post);
  ASSERT_EQ(post->status, 200) << post->body;
  const json answers = json::parse(post->body);
  ASSERT_EQ(answers.size(), 2u);
  EXPECT_EQ(answers[0].at("extreme_tension_lbf"), expected.at("extreme_tension_lbf"));
  EXPECT_EQ(answers[1].at("field"), "speed_kt");
}

TEST_F(CliServe, BadRequestsName400TheField) {  // cli-serve-3
  auto c = server_->client();
  const std::string base = "/api/query?tug=T-ATF&tow=FFG7&line=fiber&wind_kt=30&heading_deg=150";
  const struct {
    std::string path, field, needle;
  } cases[] = {
      {base + "&length_ft=1200&speed_kt=abc", "speed_kt", "not a finite number"},
      {base + "&length_ft=1200&speed_kt=30", "speed_kt", "outside the stored range [5, 9]"},
      {"/api/query?tug=Hercules&tow=FFG7&line=fiber&wind_kt=30&heading_deg=150&length_ft=1200&speed_kt=7", "tug",
       "Hercules"},
      {base + "&length_ft=1200&speed_kt=7&colour=red", "colour", "unknown field"},
      {base + "&speed_kt=7", "length_ft", "required"},
      {"/api/plan?tug=T-ATF&tow=FFG7&line=fiber&wind_kt=30&heading_deg=150&length_ft=1200&speed_kt=7"
       "&curve_headings_deg=0,400",
       "curve_headings_deg", "[0, 360]"},
  };
  for (const auto& k : cases) {
    const json e = get_json(c, k.path, 400);
    EXPECT_EQ(e.value("field", json()), k.field) << k.path;
    EXPECT_NE(e.value("error", std::string()).find(k.needle), std::string::npos) << e.dump();
  }
  const auto bad_json = c.Post("/api/query", "{not json", "application/json");
  ASSERT_TRUE(bad_json);
  EXPECT_EQ(bad_json->status, 400);
  json many = json::array();
  for (int i = 0; i < 101; ++i) many.push_back(json::object());
  const auto too_many = c.Post("/api/query", many.dump(), "application/json");
  ASSERT_TRUE(too_many);
  EXPECT_EQ(too_many->status, 400);
  EXPECT_NE(too_many->body.find("at most 100"), std::string::npos);
  const auto huge = c.Post("/api/query", std::string(70 * 1024, ' '), "application/json");
  ASSERT_TRUE(huge);
  EXPECT_EQ(huge->status, 413);
  const auto long_uri = c.Get(("/api/query?tug=" + std::string(9 * 1024, 'x')).c_str());
  ASSERT_TRUE(long_uri);
  EXPECT_EQ(long_uri->status, 414);
}

TEST(CliServeLimits, RateLimitAnswers429) {  // cli-serve-4
  ServerProcess server({"--db", "db/towdb.sqlite", "--rate-limit-per-s", "5"});
  auto c = server.client();
  int ok = 0, limited = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < 30; ++i) {
    const auto r = c.Get("/api/vessels");
    ASSERT_TRUE(r);
    if (r->status == 200) ++ok;
    if (r->status == 429) {
      ++limited;
      EXPECT_EQ(r->get_header_value("Retry-After"), "1");
    }
  }
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_GE(ok, 10);  // the burst of 2 x 5
  EXPECT_LE(ok, 10 + static_cast<int>(std::ceil(5.0 * elapsed_s)));  // plus what refilled meanwhile
  EXPECT_GE(limited, 1);
  EXPECT_EQ(ok + limited, 30);
}

TEST(CliServeLimits, DatabaseIsReadOnly) {  // cli-serve-5
  const auto dir = make_temp_dir("towdb-serve-ro");
  const auto db = dir / "towdb.sqlite";
  std::filesystem::copy_file(source_dir() / "db" / "towdb.sqlite", db);
  std::filesystem::permissions(db, std::filesystem::perms::owner_read | std::filesystem::perms::group_read);
  const std::string before = read_text(db);
  {
    ServerProcess server({"--db", db.string()});
    auto c = server.client();
    get_json(c, "/api/query?" + kReadmeQuery, 200);
    EXPECT_EQ(server.stop(), 0);
  }
  EXPECT_TRUE(read_text(db) == before);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
  std::filesystem::remove_all(dir);
}

TEST_F(CliServe, LoadTwoThousandRequestsFromEightClients) {  // cli-serve-6
  constexpr int kClients = 8, kPerClient = 250;
  // Eight questions (headings), each client cycling through them; the expected
  // answers are fetched once first.
  std::vector<std::string> paths;
  std::vector<std::string> expected;
  auto c0 = server_->client();
  for (int h = 0; h <= 175; h += 25) {
    paths.push_back("/api/query?tug=T-ATF&tow=FFG7&line=fiber&speed_kt=7&wind_kt=30&length_ft=1200&heading_deg=" +
                    std::to_string(h));
    const auto r = c0.Get(paths.back().c_str());
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200);
    expected.push_back(r->body);
  }
  std::vector<std::vector<double>> latency_ms(kClients);
  std::atomic<int> errors{0};
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::thread> clients;
  for (int k = 0; k < kClients; ++k) {
    clients.emplace_back([&, k] {
      httplib::Client c("127.0.0.1", server_->port());
      c.set_keep_alive(true);
      c.set_tcp_nodelay(true);
      c.set_read_timeout(10, 0);
      for (int i = 0; i < kPerClient; ++i) {
        const std::size_t q = static_cast<std::size_t>(k + i) % paths.size();
        const auto s = std::chrono::steady_clock::now();
        const auto r = c.Get(paths[q].c_str());
        latency_ms[static_cast<std::size_t>(k)].push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - s).count());
        if (!r || r->status != 200 || r->body != expected[q]) ++errors;
      }
    });
  }
  for (auto& t : clients) t.join();
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::vector<double> all;
  for (const auto& v : latency_ms) all.insert(all.end(), v.begin(), v.end());
  std::sort(all.begin(), all.end());
  ASSERT_EQ(all.size(), 2000u);
  EXPECT_EQ(errors.load(), 0);
  auto pct = [&](double p) { return all[static_cast<std::size_t>(p / 100.0 * static_cast<double>(all.size() - 1))]; };
  std::printf("towdb serve load: 2000 requests, 8 clients, %.2f s, %.0f requests/s; latency ms p50 %.3f p90 %.3f "
              "p99 %.3f max %.3f\n",
              wall_s, 2000.0 / wall_s, pct(50), pct(90), pct(99), all.back());
}

TEST(CliServeFlags, BadFlagsExit2) {  // cli-serve-7
  const CommandResult port = run_towdb("serve --db db/towdb.sqlite --port 70000");
  EXPECT_EQ(port.exit_code, 2);
  EXPECT_NE(port.err.find("--port"), std::string::npos) << port.err;
  EXPECT_NE(port.err.find("70000"), std::string::npos) << port.err;
  const CommandResult db = run_towdb("serve --db no-such.sqlite --port 0");
  EXPECT_EQ(db.exit_code, 2);
  EXPECT_NE(db.err.find("--db = no-such.sqlite"), std::string::npos) << db.err;
  // An address no interface of this machine has (TEST-NET-1, RFC 5737; numeric, so
  // no name lookup is involved).
  const CommandResult bind = run_towdb("serve --db db/towdb.sqlite --port 0 --bind 192.0.2.1");
  EXPECT_EQ(bind.exit_code, 2) << bind.err;
  EXPECT_NE(bind.err.find("--bind = 192.0.2.1"), std::string::npos) << bind.err;
}

}  // namespace
}  // namespace towdb::test
