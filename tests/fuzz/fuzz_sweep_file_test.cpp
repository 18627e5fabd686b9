// Fuzzer of the sweep file parser and expander (generator/sweep/spec/sweep_file:
// parse_sweep, expand_sweep), seeded from db/sweeps/ and the unit tests'
// small sweep (tests/fuzz/corpus/sweeps). Properties (issue 20 items 2-3;
// docs/hardening.md):
//   - parse_sweep either returns or throws towdb::InputError whose message
//     starts with the file name and names a key of the format; nothing else;
//   - a sweep that parses round-trips: towdb has no sweep writer, so toml++'s
//     formatter writes the document back and it must parse to the same sweep
//     (every list, sea, level and setting, bit for bit; source lines aside);
//   - a small parsed sweep (<= kMaxExpandedCases cells) also expands, or is
//     refused with an InputError that names the file, the entry and a key.
// Test plan:
//   fuzz-sweep-1  the corpus files parse and round-trip
//   fuzz-sweep-2  the kept regression inputs (tests/fuzz/regressions/sweeps) keep the properties
//   fuzz-sweep-3  seeded mutations keep the properties
#include <chrono>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <typeinfo>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "common/error.hpp"
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "sweep/spec/sweep_file.hpp"
#include "test_support.hpp"

namespace towdb::fuzz {
namespace {

const std::string kPath = "fuzz.toml";

// A sweep with at most this many grid cells (before skips) is also expanded:
// expansion computes a calculated mean tension per cell, so it is bounded to
// keep the budget on the parser.
constexpr std::size_t kMaxExpandedCases = 200;

std::string hex(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

std::string hex(const std::optional<double>& v) { return v ? hex(*v) : "-"; }

std::string describe(const sweep::SeaSpec& s) {
  std::string out = std::to_string(static_cast<int>(s.kind)) + " " + hex(s.wind_kt) + " " + hex(s.hs_ft) + " " +
                    hex(s.tp_s) + " " + hex(s.gamma);
  if (s.swell) out += " swell " + hex(s.swell->hs_ft) + " " + hex(s.swell->tp_s) + " " + hex(s.swell->heading_deg);
  return out;
}

std::string describe(const sweep::MeanTensionModel& m) {
  return hex(m.hull_margin) + " " + std::to_string(static_cast<int>(m.propeller)) + " " +
         std::to_string(static_cast<int>(m.wind)) + " " + hex(m.limit_lbf) + " " + hex(m.speed_step_kt) + " " +
         hex(m.min_speed_kt) + " " + std::to_string(static_cast<int>(m.sea_resistance));
}

// Everything parse_sweep produced except the file hash and source lines
// (both change when the document is written back).
std::string describe(const sweep::SweepFile& f) {
  std::ostringstream os;
  os << f.description << "\n";
  for (const auto& g : f.grids) {
    os << "grid " << g.label << " note " << g.coverage_note << " days " << g.days << " seed " << g.base_seed << " model " << describe(g.mean_model)
       << "\n";
    for (const auto& x : g.tugs) os << " tug " << x << "\n";
    for (const auto& x : g.tows) os << " tow " << x << "\n";
    for (double x : g.speeds_kt) os << " speed " << hex(x) << "\n";
    for (const auto& x : g.seas) os << " sea " << describe(x) << "\n";
    for (double x : g.headings_deg) os << " heading " << hex(x) << "\n";
    for (const auto& x : g.towlines) os << " towline " << static_cast<int>(x.line) << " " << hex(x.length_ft) << "\n";
    for (const auto& x : g.mean_tensions) {
      os << " level " << x.label << " " << static_cast<int>(x.basis) << " " << hex(x.factor) << " " << hex(x.value_lbf)
         << "\n";
    }
  }
  for (const auto& c : f.cases) {
    const sweep::CaseSpec& s = c.spec;
    os << "case " << c.label << " seed " << (c.seed ? std::to_string(*c.seed) : "-") << " base " << c.base_seed << " "
       << s.tug << "|" << s.tow << " " << hex(s.speed_kt) << " " << describe(s.sea) << " " << hex(s.heading_deg) << " "
       << static_cast<int>(s.line) << " " << hex(s.length_ft) << " " << hex(s.mean_tension_lbf) << " "
       << s.mean_tension_label << " " << s.days << "\n";
  }
  return os.str();
}

std::size_t cell_count(const sweep::SweepFile& f) {
  std::size_t n = f.cases.size();
  for (const auto& g : f.grids) {
    n += g.tugs.size() * g.tows.size() * g.speeds_kt.size() * g.seas.size() * g.headings_deg.size() *
         g.towlines.size() * g.mean_tensions.size();
  }
  return n;
}

const io::ShipCatalog& catalog() {
  static const io::ShipCatalog c = io::ShipCatalog::load(test::source_dir() / "ships");
  return c;
}

std::string reformat(const std::string& text) {
  std::ostringstream os;
  os << toml::toml_formatter(toml::parse(text, kPath));
  return os.str();
}

// Checks one input; "" when every property holds, else the problem.
std::string check_input(const std::string& text, const std::vector<std::string>& fields, Tally& tally,
                        int* expanded) {
  ++tally.executions;
  std::optional<sweep::SweepFile> parsed;
  try {
    parsed = sweep::parse_sweep(text, kPath);
  } catch (const InputError& e) {
    ++tally.refused;
    tally.distinct_messages.insert(std::string(e.what()).substr(0, 60));
    const std::string problem = refusal_problem(e.what(), kPath, fields);
    return problem.empty() ? "" : problem + ": " + e.what();
  } catch (const std::exception& e) {
    return std::string("parse: not an InputError (") + typeid(e).name() + "): " + e.what();
  }
  ++tally.accepted;
  const std::string again_text = reformat(text);
  try {
    const sweep::SweepFile again = sweep::parse_sweep(again_text, kPath);
    if (describe(*parsed) != describe(again)) {
      return "round trip: the re-formatted file parses to a different sweep\n--- first:\n" + describe(*parsed) +
             "--- again:\n" + describe(again);
    }
  } catch (const std::exception& e) {
    return std::string("round trip: the re-formatted file is refused: ") + e.what() + "\n" + again_text;
  }
  if (cell_count(*parsed) > kMaxExpandedCases) return "";
  ++*expanded;
  try {
    sweep::expand_sweep(*parsed, catalog());
  } catch (const InputError& e) {
    const std::string problem = refusal_problem(e.what(), kPath, fields);
    return problem.empty() ? "" : "expand: " + problem + ": " + e.what();
  } catch (const std::exception& e) {
    return std::string("expand: not an InputError (") + typeid(e).name() + "): " + e.what();
  }
  return "";
}

// The sweep format's keys plus the vessel words an expansion error may name.
std::vector<std::string> sweep_fields(const Mutator& m) {
  std::vector<std::string> f = field_names(m.words());
  for (const char* extra : {"grid", "case", "vessel", "towline", "breaking", "seas", "spectrum"}) f.push_back(extra);
  return f;
}

TEST(FuzzSweepFile, CorpusParsesAndRoundTrips) {  // fuzz-sweep-1
  const auto corpus = load_dir("corpus/sweeps");
  ASSERT_GE(corpus.size(), 4u);
  const Mutator m(corpus);
  for (const Input& in : corpus) {
    Tally tally;
    int expanded = 0;
    EXPECT_EQ(check_input(in.text, sweep_fields(m), tally, &expanded), "") << in.name;
    EXPECT_EQ(tally.accepted, 1) << in.name << " does not parse";
  }
}

TEST(FuzzSweepFile, RegressionInputsKeepTheProperties) {  // fuzz-sweep-2
  const Mutator m(load_dir("corpus/sweeps"));
  const auto kept = load_dir("regressions/sweeps");
  ASSERT_FALSE(kept.empty()) << "no inputs under tests/fuzz/regressions/sweeps";
  for (const Input& in : kept) {
    Tally tally;
    int expanded = 0;
    EXPECT_EQ(check_input(in.text, sweep_fields(m), tally, &expanded), "") << in.name;
  }
}

TEST(FuzzSweepFile, MutatedSweepFiles) {  // fuzz-sweep-3
  const auto corpus = load_dir("corpus/sweeps");
  ASSERT_FALSE(corpus.empty());
  const Mutator mutator(corpus);
  const auto fields = sweep_fields(mutator);
  Findings findings("sweeps");
  Tally tally;
  int expanded = 0;
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t s = seed(20003);
  const int n = iterations(20000);
  for (int i = 0; i < n; ++i) {
    RandomStream rng(s, static_cast<std::uint64_t>(i));
    const Input& base = corpus[below(rng, corpus.size())];
    const std::string text = mutator.mutate(rng, base.text);
    const std::string problem = check_input(text, fields, tally, &expanded);
    if (!problem.empty() &&
        !findings.report("seed" + std::to_string(s) + "-iter" + std::to_string(i) + "-" + base.name, text, problem)) {
      break;
    }
  }
  tally.print("sweeps", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  std::cout << "fuzz sweeps: " << expanded << " parsed sweeps also expanded\n";
  EXPECT_GT(tally.accepted, 0);
  EXPECT_GT(tally.refused, 0);
}

}  // namespace
}  // namespace towdb::fuzz
