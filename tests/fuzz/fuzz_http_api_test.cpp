// Fuzzer of the HTTP API of `towdb serve` (issue 20 item 2; docs/hardening.md):
// mutated requests (method line, query string and JSON body, seeded from
// tests/fuzz/corpus/http) sent on loopback to a server on the bundled
// database. Properties (cli/cmd_serve.cpp, docs/planner-tools.md):
//   - every request gets an answer: the server never dies or hangs;
//   - the status is 200, 400, 404/405 (a path or method the API does not
//     have), 413 (body over 64 KiB) or 414 (URI over 8 KiB); never 5xx;
//   - every /api/ answer is JSON; a 400 is {"error": text, "field": name}
//     with both non-empty; a 200 from /api/query is an answer with a finite
//     extreme tension, or, for a posted list, one answer or {error, field}
//     per question;
//   - after the run the server still answers and stops with exit 0.
// Test plan:
//   fuzz-http-1  the corpus requests keep the properties (and are answered 200)
//   fuzz-http-2  the kept regression inputs (tests/fuzz/regressions/http) keep the properties
//   fuzz-http-3  seeded mutations keep the properties
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "serve_process.hpp"
#include "test_support.hpp"

namespace towdb::fuzz {
namespace {

using nlohmann::json;

const std::vector<std::string> kFields = {"tug",      "tow",         "line",      "spectrum",         "speed_kt",
                                          "wind_kt",  "hs_ft",       "tp_s",      "heading_deg",      "length_ft",
                                          "mean_tension_lbf", "probability", "tow_days", "brake", "curve_headings_deg",
                                          "api",      "query",       "plan",      "vessels"};

struct HttpRequest {
  bool post = false;
  std::string path;  // percent-encoded where needed
  std::string body;
};

// Keeps the bytes a query string may carry as they are (so that the mutator's
// '&', '=' and '%' edits reach the server's parser) and percent-encodes the
// rest, so that every mutated request is valid HTTP on the wire.
std::string encode_path(const std::string& raw) {
  static const std::string keep = "-._~&=/?%,+:;!$'()*@";
  std::string out;
  for (unsigned char c : raw) {
    if (std::isalnum(c) || keep.find(static_cast<char>(c)) != std::string::npos) {
      out.push_back(static_cast<char>(c));
    } else {
      static const char* hex = "0123456789ABCDEF";
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (out.empty() || out.front() != '/') out.insert(out.begin(), '/');
  return out;
}

// "METHOD PATH\nBODY": the first line's first word picks GET or POST.
HttpRequest parse_request(const std::string& text) {
  HttpRequest r;
  const auto nl = text.find('\n');
  const std::string first = text.substr(0, nl);
  r.body = nl == std::string::npos ? "" : text.substr(nl + 1);
  const auto sp = first.find(' ');
  r.post = first.rfind("POST", 0) == 0;
  r.path = encode_path(sp == std::string::npos ? first : first.substr(sp + 1));
  return r;
}

std::string check_error_object(const json& e, const std::string& where) {
  if (!e.is_object() || !e.contains("error") || !e.contains("field")) return "an error is not {error, field}" + where;
  if (!e["error"].is_string() || e["error"].get<std::string>().empty()) return "an error has no message" + where;
  if (!e["field"].is_string() || e["field"].get<std::string>().empty()) {
    return "an error names no field: " + e["error"].dump() + where;
  }
  return "";
}

std::string check_answer_object(const json& a, const std::string& where) {
  if (!a.is_object()) return "an answer is not a JSON object" + where;
  if (a.contains("error")) return check_error_object(a, where);
  const auto it = a.find("extreme_tension_lbf");
  if (it == a.end() || !it->is_number() || !std::isfinite(it->get<double>())) {
    return "an answer has no finite extreme_tension_lbf" + where;
  }
  return "";
}

// Sends one request and checks its answer; "" when every property holds.
std::string check_request(httplib::Client& c, const HttpRequest& rq, Tally& tally) {
  ++tally.executions;
  const auto res = rq.post ? c.Post(rq.path, rq.body, "application/json") : c.Get(rq.path);
  const std::string where = "\n  " + std::string(rq.post ? "POST " : "GET ") + rq.path.substr(0, 300);
  if (!res) return "no answer (server dead or hung): " + httplib::to_string(res.error()) + where;
  const int st = res->status;
  const std::string body_where = where + "\n  status " + std::to_string(st) + ": " + res->body.substr(0, 300);
  if (st != 200 && st != 400 && st != 404 && st != 405 && st != 413 && st != 414) {
    return "status " + std::to_string(st) + body_where;
  }
  st == 200 ? ++tally.accepted : ++tally.refused;
  const bool api = rq.path.rfind("/api/", 0) == 0;
  if (!api || st == 404 || st == 405 || st == 413 || st == 414) return "";
  json j;
  try {
    j = json::parse(res->body);
  } catch (const std::exception& e) {
    return std::string("the answer is not JSON: ") + e.what() + body_where;
  }
  if (st == 400) {
    tally.distinct_messages.insert(j.value("error", std::string()).substr(0, 60));
    return check_error_object(j, body_where);
  }
  if (rq.path.rfind("/api/query", 0) != 0) return "";
  if (j.is_array()) {
    for (const json& a : j) {
      if (std::string p = check_answer_object(a, body_where); !p.empty()) return p;
    }
    return "";
  }
  return check_answer_object(j, body_where);
}

class FuzzHttpApi : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    server_ = new test::ServerProcess(
        {"--db", (test::source_dir() / "db" / "towdb.sqlite").string(), "--rate-limit-per-s", "1e5"});
  }
  static void TearDownTestSuite() {
    auto c = server_->client();
    const auto alive = c.Get("/api/vessels");
    EXPECT_TRUE(alive && alive->status == 200) << "the server does not answer after the fuzzer";
    EXPECT_EQ(server_->stop(), 0) << "the server did not stop cleanly";
    delete server_;
  }
  static test::ServerProcess* server_;
};
test::ServerProcess* FuzzHttpApi::server_ = nullptr;

TEST_F(FuzzHttpApi, CorpusKeepsTheProperties) {  // fuzz-http-1
  auto c = server_->client();
  const auto corpus = load_dir("corpus/http");
  ASSERT_FALSE(corpus.empty());
  for (const Input& in : corpus) {
    Tally tally;
    EXPECT_EQ(check_request(c, parse_request(in.text), tally), "") << in.name;
    EXPECT_EQ(tally.accepted, 1) << in.name << " is not answered 200";
  }
}

TEST_F(FuzzHttpApi, RegressionInputsKeepTheProperties) {  // fuzz-http-2
  auto c = server_->client();
  const auto kept = load_dir("regressions/http");
  ASSERT_FALSE(kept.empty());
  for (const Input& in : kept) {
    Tally tally;
    EXPECT_EQ(check_request(c, parse_request(in.text), tally), "") << in.name;
  }
}

TEST_F(FuzzHttpApi, MutatedRequests) {  // fuzz-http-3
  auto c = server_->client();
  const auto corpus = load_dir("corpus/http");
  ASSERT_FALSE(corpus.empty());
  std::vector<std::string> words = kFields;
  for (const char* w : {"T-ATF 166", "ARS 50", "LHA 1", "FFG 7", "YRBM", "wire", "fiber", "jonswap", "GET", "POST"}) {
    words.push_back(w);
  }
  const Mutator mutator(corpus, words);
  Findings findings("http");
  Tally tally;
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t s = seed(30011);
  const int n = iterations(3000);
  for (int i = 0; i < n; ++i) {
    RandomStream rng(s, static_cast<std::uint64_t>(i));
    const Input& base = corpus[below(rng, corpus.size())];
    const std::string text = mutator.mutate(rng, base.text);
    const std::string problem = check_request(c, parse_request(text), tally);
    if (!problem.empty() &&
        !findings.report("seed" + std::to_string(s) + "-iter" + std::to_string(i) + "-" + base.name, text, problem)) {
      break;
    }
  }
  tally.print("http", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  EXPECT_GT(tally.accepted, 0);
  EXPECT_GT(tally.refused, 0);
}

}  // namespace
}  // namespace towdb::fuzz
