// Fuzzer of the query library's C API (query/include/towdb/query.h): random
// requests (NaN, inf, huge and subnormal values, NULL and empty strings,
// unknown and prefix names, odd flags) through every entry point, on the
// fuzz database (fuzz_db.hpp). Properties (issue 20 items 2-3;
// docs/hardening.md, query.h "ERRORS AND OWNERSHIP"):
//   - every call returns TOWDB_QUERY_OK or the documented input codes:
//     TOWDB_QUERY_INPUT or _RANGE (TOWDB_QUERY_NUMERICAL only when
//     extrapolation was asked for, TOWDB_QUERY_MISUSE only for a NULL pointer,
//     never _ERROR, _NOMEM or _DATABASE on a good database); errcode() agrees;
//   - a refusal's errmsg names a request field (or, for a missing grid node,
//     the node); after success errmsg is "";
//   - an answer is finite and self-consistent: extreme = mean + 1000 dynamic,
//     limits BS/1.5 and BS/3 or BS/5, the checks agree with them, alpha > 0,
//     not extrapolated unless asked, warning and nearest lists as counted;
//   - a search's value lies in its searched range (NaN when not found);
//   - the same request twice gives bit-identical results.
// Test plan:
//   fuzz-api-1  the kept regression requests (tests/fuzz/regressions/query_requests) keep the properties
//   fuzz-api-2  seeded random requests keep the properties
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz_checks.hpp"
#include "fuzz_db.hpp"
#include "fuzz_query_checks.hpp"
#include "fuzz_support.hpp"
#include "test_support.hpp"
#include "towdb/query.h"

namespace towdb::fuzz {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

enum class Entry { kRun, kMaxSpeed, kMinLength, kLeaveOneOut };

// One fuzzed call: the request with its strings owned here, and which NULLs.
struct Call {
  Entry entry = Entry::kRun;
  std::optional<std::string> tug, tow, line, spectrum;  // nullopt: NULL
  towdb_query_request r{};
  int space = TOWDB_QUERY_SPACE_LINEAR, axis = TOWDB_QUERY_AXIS_ALL;  // leave-one-out
  bool null_request = false, null_result = false, null_at_value = false;
};

std::string hex(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

// The regression file format: one "key = value" per line; strings in
// double quotes with \xHH escapes, <NULL> for a NULL pointer; doubles in C
// hex-float, nan or inf (strtod syntax).
std::string escape(const std::optional<std::string>& s) {
  if (!s) return "<NULL>";
  std::string out = "\"";
  for (unsigned char c : *s) {
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  return out + "\"";
}

std::optional<std::string> unescape(const std::string& v) {
  if (v == "<NULL>") return std::nullopt;
  std::string out;
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    if (v[i] == '\\' && i + 3 < v.size() && v[i + 1] == 'x') {
      out += static_cast<char>(std::strtol(v.substr(i + 2, 2).c_str(), nullptr, 16));
      i += 3;
    } else {
      out += v[i];
    }
  }
  return out;
}

const char* const kEntryNames[] = {"run", "max_speed", "min_length", "leave_one_out"};

std::string serialize(const Call& c) {
  std::ostringstream os;
  os << "entry = " << kEntryNames[static_cast<int>(c.entry)] << "\ntug = " << escape(c.tug)
     << "\ntow = " << escape(c.tow) << "\nline = " << escape(c.line) << "\nspectrum = " << escape(c.spectrum) << "\n";
  const towdb_query_request& r = c.r;
  const std::pair<const char*, double> numbers[] = {
      {"speed_kt", r.speed_kt},       {"wind_kt", r.wind_kt},     {"hs_ft", r.hs_ft},
      {"tp_s", r.tp_s},               {"heading_deg", r.heading_deg}, {"length_ft", r.length_ft},
      {"mean_tension_lbf", r.mean_tension_lbf}, {"probability", r.probability}, {"tow_days", r.tow_days}};
  for (const auto& [k, v] : numbers) os << k << " = " << hex(v) << "\n";
  os << "extrapolate = " << r.extrapolate << "\non_brake = " << r.on_brake << "\nspace = " << c.space
     << "\naxis = " << c.axis << "\nnull_request = " << c.null_request << "\nnull_result = " << c.null_result
     << "\nnull_at_value = " << c.null_at_value << "\n";
  return os.str();
}

Call deserialize(const std::string& text) {
  Call c;
  towdb_query_request_init(&c.r);
  std::istringstream is(text);
  for (std::string line; std::getline(is, line);) {
    const auto eq = line.find(" = ");
    if (line.empty() || line[0] == '#' || eq == std::string::npos) continue;
    const std::string k = line.substr(0, eq), v = line.substr(eq + 3);
    double* numbers[] = {&c.r.speed_kt, &c.r.wind_kt, &c.r.hs_ft, &c.r.tp_s, &c.r.heading_deg,
                         &c.r.length_ft, &c.r.mean_tension_lbf, &c.r.probability, &c.r.tow_days};
    const char* names[] = {"speed_kt", "wind_kt", "hs_ft", "tp_s", "heading_deg",
                           "length_ft", "mean_tension_lbf", "probability", "tow_days"};
    for (std::size_t i = 0; i < std::size(names); ++i) {
      if (k == names[i]) *numbers[i] = std::strtod(v.c_str(), nullptr);
    }
    for (int e = 0; e < 4; ++e) {
      if (k == "entry" && v == kEntryNames[e]) c.entry = static_cast<Entry>(e);
    }
    if (k == "tug") c.tug = unescape(v);
    if (k == "tow") c.tow = unescape(v);
    if (k == "line") c.line = unescape(v);
    if (k == "spectrum") c.spectrum = unescape(v);
    if (k == "extrapolate") c.r.extrapolate = std::atoi(v.c_str());
    if (k == "on_brake") c.r.on_brake = std::atoi(v.c_str());
    if (k == "space") c.space = std::atoi(v.c_str());
    if (k == "axis") c.axis = std::atoi(v.c_str());
    if (k == "null_request") c.null_request = v == "1";
    if (k == "null_result") c.null_result = v == "1";
    if (k == "null_at_value") c.null_at_value = v == "1";
  }
  return c;
}

// A value for a numeric field: mostly plausible (around the stored range
// [lo, hi], half a range beyond each end), sometimes a stored node exactly,
// sometimes an odd double.
double draw(RandomStream& rng, double lo, double hi, const std::vector<double>& nodes) {
  const double p = rng.uniform01();
  if (p < 0.55) return lo - 0.5 * (hi - lo) + 2.0 * (hi - lo) * rng.uniform01();
  if (p < 0.75) return nodes[below(rng, nodes.size())];
  if (p < 0.85) return kNaN;
  return odd_doubles()[below(rng, odd_doubles().size())];
}

std::optional<std::string> draw_name(RandomStream& rng, const std::vector<std::string>& good) {
  const double p = rng.uniform01();
  if (p < 0.7) return good[below(rng, good.size())];
  if (p < 0.75) return std::nullopt;
  const auto& odd = odd_strings();
  return odd[below(rng, odd.size())];
}

// A valid request for one of the three groups of the fuzz database, with
// in-range values (the stored range of each axis).
void valid_request(RandomStream& rng, Call* c) {
  towdb_query_request& r = c->r;
  auto in = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform01(); };
  switch (below(rng, 3)) {
    case 0:
      c->tug = "T-ATF 166", c->tow = "LHA 1", c->line = "wire";
      r.wind_kt = in(20.0, 35.0);
      r.length_ft = in(1000.0, 2000.0);
      if (chance(rng, 0.5)) r.mean_tension_lbf = in(0.7, 1.1) * (30000.0 + 6000.0 * 7.0 + 500.0 * r.wind_kt);
      break;
    case 1:
      c->tug = "ARS 50", c->tow = "FFG 7", c->line = "fiber";
      r.wind_kt = in(20.0, 35.0);
      r.length_ft = in(800.0, 1500.0);
      break;
    default:
      c->tug = "ARS 50", c->tow = "LHA 1", c->line = "wire";
      r.hs_ft = in(8.0, 16.0);
      r.tp_s = in(8.0, 10.0);
      r.length_ft = 1500.0;
      r.mean_tension_lbf = in(50000.0, 70000.0);
      break;
  }
  r.speed_kt = in(5.0, 9.0);
  r.heading_deg = in(0.0, 360.0);
}

// A request for the fuzzer: a valid one with 0-3 fields replaced by drawn
// values (plausible, node, NaN or odd), or (one call in four) every field drawn.
Call random_call(RandomStream& rng) {
  Call c;
  towdb_query_request_init(&c.r);
  const double e = rng.uniform01();
  c.entry = e < 0.6 ? Entry::kRun : e < 0.78 ? Entry::kMaxSpeed : e < 0.96 ? Entry::kMinLength : Entry::kLeaveOneOut;
  valid_request(rng, &c);
  towdb_query_request& r = c.r;
  const bool all = chance(rng, 0.25);
  const std::size_t edits = all ? 15 : below(rng, 4);
  for (std::size_t k = 0; k < edits; ++k) {
    switch (all ? k : below(rng, 15)) {
      case 0: c.tug = draw_name(rng, {"T-ATF 166", "ARS 50", "tatf", "ars-50", "T-ATF"}); break;
      case 1: c.tow = draw_name(rng, {"LHA 1", "FFG 7", "lha1", "ffg", "LHA"}); break;
      case 2: c.line = draw_name(rng, {"wire", "fiber", "wire", "fiber", "chain"}); break;
      case 3: c.spectrum = draw_name(rng, {"jonswap", "pierson-moskowitz", "jonswap(gamma=3.3)"}); break;
      case 4: r.speed_kt = draw(rng, 5.0, 9.0, {5.0, 7.0, 9.0}); break;
      case 5: r.wind_kt = draw(rng, 20.0, 35.0, {20.0, 30.0, 35.0}); break;
      case 6: r.hs_ft = draw(rng, 8.0, 16.0, {8.0, 12.0, 16.0}); break;
      case 7: r.tp_s = draw(rng, 8.0, 10.0, {8.0, 10.0}); break;
      case 8: r.heading_deg = draw(rng, 0.0, 360.0, {0.0, 90.0, 180.0, 270.0, 360.0}); break;
      case 9: r.length_ft = draw(rng, 800.0, 2000.0, {800.0, 1000.0, 1500.0, 2000.0}); break;
      case 10: r.mean_tension_lbf = draw(rng, 20000.0, 120000.0, {50000.0, 70000.0}); break;
      case 11: r.probability = draw(rng, 0.0, 0.5, {0.001, 0.01, 0.5}); break;
      case 12: r.tow_days = draw(rng, 1.0, 60.0, {1.0, 10.0}); break;
      case 13: {
        const int flags[] = {0, 1, 2, -1, 1 << 30};
        r.extrapolate = flags[below(rng, std::size(flags))];
        break;
      }
      default: r.on_brake = chance(rng, 0.5) ? 1 : (chance(rng, 0.5) ? -3 : 7); break;
    }
  }
  c.space = static_cast<int>(below(rng, 4)) - (chance(rng, 0.1) ? 5 : 0);
  c.axis = static_cast<int>(below(rng, 9)) - 2;
  c.null_request = chance(rng, 0.02);
  c.null_result = chance(rng, 0.02);
  c.null_at_value = chance(rng, 0.3);
  return c;
}

const char* const kFields[] = {"tug", "tow", "line", "spectrum", "speed_kt", "wind_kt", "hs_ft", "tp_s",
                               "heading_deg", "length_ft", "mean_tension_lbf", "probability", "tow_days",
                               "space", "axis", "no stored case at"};

// Calls the entry point; returns the code and fills the outputs.
struct Outputs {
  towdb_query_result result{};
  towdb_query_search search{};
  towdb_query_loo loo{};
};

int invoke(towdb_query_db* db, Call& c, Outputs* o) {
  c.r.tug = c.tug ? c.tug->c_str() : nullptr;
  c.r.tow = c.tow ? c.tow->c_str() : nullptr;
  c.r.line = c.line ? c.line->c_str() : nullptr;
  c.r.spectrum = c.spectrum ? c.spectrum->c_str() : nullptr;
  const towdb_query_request* req = c.null_request ? nullptr : &c.r;
  switch (c.entry) {
    case Entry::kRun: return towdb_query_run(db, req, c.null_result ? nullptr : &o->result);
    case Entry::kMaxSpeed:
      return towdb_query_max_speed(db, req, c.null_result ? nullptr : &o->search, c.null_at_value ? nullptr : &o->result);
    case Entry::kMinLength:
      return towdb_query_min_length(db, req, c.null_result ? nullptr : &o->search, c.null_at_value ? nullptr : &o->result);
    case Entry::kLeaveOneOut:
      return towdb_query_leave_one_out(db, c.space, c.axis, c.null_result ? nullptr : &o->loo);
  }
  return -1;
}

bool is_null_call(const Call& c) {
  return c.entry == Entry::kLeaveOneOut ? c.null_result : (c.null_request || c.null_result);
}

// Runs one call and checks every property; "" when they hold.
std::string check_call(towdb_query_db* db, Call c, Tally& tally) {
  ++tally.executions;
  Outputs o;
  const int code = invoke(db, c, &o);
  if (code != towdb_query_errcode(db)) return "errcode() = " + std::to_string(towdb_query_errcode(db)) + " != " + std::to_string(code);
  const std::string msg = towdb_query_errmsg(db);
  if (code == TOWDB_QUERY_MISUSE) {
    if (!is_null_call(c)) return "TOWDB_QUERY_MISUSE without a NULL pointer: " + msg;
    return msg.empty() ? "TOWDB_QUERY_MISUSE without a message" : "";
  }
  if (is_null_call(c)) return "a NULL pointer was not refused with TOWDB_QUERY_MISUSE (code " + std::to_string(code) + ")";
  if (code != TOWDB_QUERY_OK) {
    ++tally.refused;
    tally.distinct_messages.insert(msg.substr(0, 60));
    const bool allowed = code == TOWDB_QUERY_INPUT || code == TOWDB_QUERY_RANGE ||
                         (code == TOWDB_QUERY_NUMERICAL && c.r.extrapolate != 0);
    if (!allowed) return "code " + std::to_string(code) + ": " + msg;
    for (const char* f : kFields) {
      if (msg.find(f) != std::string::npos) return "";
    }
    return "the message names no request field: " + msg;
  }
  ++tally.accepted;
  if (!msg.empty()) return "errmsg is not empty after success: " + msg;
  if (c.entry == Entry::kRun) {
    if (std::string p = check_answer(db, c.r, o.result); !p.empty()) return p;
  } else if (c.entry != Entry::kLeaveOneOut) {
    const towdb_query_search& s = o.search;
    if (s.found == 1) {
      if (!(s.value >= s.range_low && s.value <= s.range_high)) return "a found search value is outside its range";
      if (!c.null_at_value) {
        if (std::string p = check_answer(db, c.r, o.result); !p.empty()) return "at_value: " + p;
      }
    } else if (s.found != 0 || !std::isnan(s.value)) {
      return "a search that found nothing has found = " + std::to_string(s.found) + ", value = " + hex(s.value);
    }
  }
  // Determinism: the same call again gives the same bytes.
  Outputs again;
  invoke(db, c, &again);
  if (std::memcmp(&o, &again, sizeof o) != 0) return "the same request twice gives different results";
  return "";
}

class FuzzQueryApi : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(test::make_temp_dir("towdb-fuzz-api"));
    write_fuzz_db(*dir_ / "fuzz.towdb", false);
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete dir_;
  }
  static std::filesystem::path* dir_;
};
std::filesystem::path* FuzzQueryApi::dir_ = nullptr;

TEST_F(FuzzQueryApi, RegressionRequestsKeepTheProperties) {  // fuzz-api-1
  towdb_query_db* db = nullptr;
  ASSERT_EQ(towdb_query_open((*dir_ / "fuzz.towdb").c_str(), TOWDB_QUERY_SPACE_AUTO, &db), TOWDB_QUERY_OK)
      << towdb_query_errmsg(db);
  const auto kept = load_dir("regressions/query_requests");
  ASSERT_FALSE(kept.empty()) << "no inputs under tests/fuzz/regressions/query_requests";
  Tally tally;
  for (const Input& in : kept) {
    EXPECT_EQ(check_call(db, deserialize(in.text), tally), "") << in.name;
  }
  towdb_query_close(db);
}

TEST_F(FuzzQueryApi, RandomRequests) {  // fuzz-api-2
  towdb_query_db* db = nullptr;
  ASSERT_EQ(towdb_query_open((*dir_ / "fuzz.towdb").c_str(), TOWDB_QUERY_SPACE_AUTO, &db), TOWDB_QUERY_OK)
      << towdb_query_errmsg(db);
  // The NULL-handle entry points: a code, never a crash.
  towdb_query_request r;
  towdb_query_request_init(&r);
  towdb_query_request_init(nullptr);
  towdb_query_result res{};
  EXPECT_EQ(towdb_query_run(nullptr, &r, &res), TOWDB_QUERY_MISUSE);
  EXPECT_EQ(towdb_query_errcode(nullptr), TOWDB_QUERY_MISUSE);
  EXPECT_STRNE(towdb_query_errmsg(nullptr), "");
  Findings findings("query_requests");
  Tally tally;
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t s = seed(20004);
  const int n = iterations(200000);
  for (int i = 0; i < n; ++i) {
    RandomStream rng(s, static_cast<std::uint64_t>(i));
    const Call c = random_call(rng);
    const std::string problem = check_call(db, c, tally);
    if (!problem.empty() &&
        !findings.report("seed" + std::to_string(s) + "-iter" + std::to_string(i) + ".txt", serialize(c), problem)) {
      break;
    }
  }
  tally.print("query_requests", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  EXPECT_GT(tally.accepted, n / 20) << "too few requests answered to test the answers' properties";
  towdb_query_close(db);
}

}  // namespace
}  // namespace towdb::fuzz
