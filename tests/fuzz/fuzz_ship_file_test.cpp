// Fuzzer of the ship and towline file parser (generator/io: parse_vessel,
// parse_towline_component), seeded from ships/ (tests/fuzz/corpus/vessels,
// towlines). Properties (issue 20 items 2-3; docs/hardening.md):
//   - every input either parses or throws towdb::InputError (the CLI's exit 2)
//     whose message starts with the file name and names a field of the format;
//     any other exception (or a crash, caught by the sanitizer build) fails;
//   - every input that parses round-trips: towdb has no ship file writer, so
//     the document is written back by toml++'s formatter and must parse to the
//     same model, bit for bit (every number, string, station and provenance).
// Test plan:
//   fuzz-ship-1  the corpus files parse and round-trip
//   fuzz-ship-2  the kept regression inputs (tests/fuzz/regressions/vessels, towlines) keep the properties
//   fuzz-ship-3  seeded mutations of vessel files keep the properties
//   fuzz-ship-4  seeded mutations of towline component files keep the properties
#include <chrono>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <typeinfo>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "common/error.hpp"
#include "fuzz_checks.hpp"
#include "fuzz_support.hpp"
#include "io/ship_file.hpp"

namespace towdb::fuzz {
namespace {

const std::string kPath = "fuzz.toml";

// Every double as its exact bits (C99 hex float).
std::string hex(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

void describe_provenance(std::ostringstream& os, const std::vector<io::Provenance>& p) {
  for (const auto& x : p) os << "prov " << x.key << "=" << x.value << " [" << x.status << "] " << x.source << "\n";
}

// Everything parse_vessel produced except the file hash (which differs by design).
std::string describe(const io::VesselFile& f) {
  const model::Vessel& v = f.vessel;
  const model::Hull& h = v.hull;
  std::ostringstream os;
  os << v.name << "|" << static_cast<int>(v.role) << "|" << f.description << "|" << v.wire_hawser << "|"
     << v.fiber_hawser << "|" << v.pendant << "\n";
  for (const auto& a : v.aliases) os << "alias " << a << "\n";
  for (double x : {h.length_overall_m, h.length_pp_m, h.beam_m, h.draft_m, h.displacement_kg, h.lcg_m, h.kg_m, h.gm_m,
                   h.radius_gyration_roll_m, h.radius_gyration_pitch_m, h.radius_gyration_yaw_m, h.wetted_surface_m2,
                   h.windage_frontal_m2, h.roll_damping_ratio, h.surge_added_mass_ratio, v.tow_point.x_m,
                   v.tow_point.z_m}) {
    os << hex(x) << " ";
  }
  os << "\n";
  for (const auto& s : h.stations) {
    os << "st " << hex(s.x_m) << " " << hex(s.beam_m) << " " << hex(s.draft_m) << " " << hex(s.area_coefficient) << "\n";
  }
  for (std::size_t i = 0; i < v.drag.speed_m_s.size(); ++i) {
    os << "drag " << hex(v.drag.speed_m_s[i]) << " " << hex(v.drag.total_resistance_coefficient[i]) << "\n";
  }
  if (v.propellers) {
    const model::Propellers& p = *v.propellers;
    os << "prop " << p.count << " " << p.blades << " " << static_cast<int>(p.pitch) << " " << p.nozzle;
    for (double x : {p.diameter_m, p.expanded_area_ratio, p.pitch_ratio, p.rpm_max, p.wake_fraction,
                     p.thrust_deduction, p.installed_power_w}) {
      os << " " << hex(x);
    }
    os << "\n";
  }
  describe_provenance(os, f.provenance);
  return os.str();
}

std::string describe(const io::TowlineFile& f) {
  const model::TowlineComponent& c = f.component;
  std::ostringstream os;
  os << c.name << "|" << static_cast<int>(c.kind) << "|" << f.description << "\n";
  for (double x : {c.ea_n, c.hydrodynamic_diameter_m, c.mass_per_length_kg_m, c.weight_in_water_n_m,
                   c.breaking_strength_n, c.drag_coefficient_normal, c.added_mass_coefficient, c.fixed_length_m}) {
    os << hex(x) << " ";
  }
  os << "\n";
  describe_provenance(os, f.provenance);
  return os.str();
}

// The document of `text` written back by toml++ (tables, arrays, inline
// tables and every value re-spelt; comments dropped).
std::string reformat(const std::string& text) {
  std::ostringstream os;
  os << toml::toml_formatter(toml::parse(text, kPath));
  return os.str();
}

// Checks one input; "" when every property holds, else the problem.
template <typename Parse>
std::string check_input(const std::string& text, Parse parse, const std::vector<std::string>& fields, Tally& tally) {
  ++tally.executions;
  try {
    const auto parsed = parse(text, kPath);
    ++tally.accepted;
    const std::string again_text = reformat(text);
    try {
      const auto again = parse(again_text, kPath);
      if (describe(parsed) != describe(again)) {
        return "round trip: the re-formatted file parses to a different model\n--- first:\n" + describe(parsed) +
               "--- again:\n" + describe(again);
      }
    } catch (const std::exception& e) {
      return std::string("round trip: the re-formatted file is refused: ") + e.what() + "\n" + again_text;
    }
    return "";
  } catch (const InputError& e) {
    ++tally.refused;
    tally.distinct_messages.insert(std::string(e.what()).substr(0, 60));
    const std::string problem = refusal_problem(e.what(), kPath, fields);
    return problem.empty() ? "" : problem + ": " + e.what();
  } catch (const std::exception& e) {
    return std::string("not an InputError (") + typeid(e).name() + "): " + e.what();
  }
}

template <typename Parse>
void run_fuzzer(const std::string& name, const std::string& kind, std::uint64_t fixed_seed, int base_iterations,
                Parse parse) {
  const auto corpus = load_dir("corpus/" + kind);
  ASSERT_FALSE(corpus.empty()) << "no corpus under tests/fuzz/corpus/" << kind;
  const Mutator mutator(corpus);
  const auto fields = field_names(mutator.words());
  Findings findings(name);
  Tally tally;
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t s = seed(fixed_seed);
  const int n = iterations(base_iterations);
  for (int i = 0; i < n; ++i) {
    RandomStream rng(s, static_cast<std::uint64_t>(i));
    const Input& base = corpus[below(rng, corpus.size())];
    const std::string text = mutator.mutate(rng, base.text);
    const std::string problem = check_input(text, parse, fields, tally);
    if (!problem.empty() &&
        !findings.report("seed" + std::to_string(s) + "-iter" + std::to_string(i) + "-" + base.name, text, problem)) {
      break;
    }
  }
  tally.print(name, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  EXPECT_GT(tally.accepted, 0) << "no mutated input parsed: the mutations are too destructive to test round trips";
  EXPECT_GT(tally.refused, 0);
}

const auto kParseVessel = [](const std::string& text, const std::string& path) { return io::parse_vessel(text, path); };
const auto kParseTowline = [](const std::string& text, const std::string& path) {
  return io::parse_towline_component(text, path);
};

template <typename Parse>
void check_files(const std::vector<Input>& files, Parse parse, bool must_parse) {
  ASSERT_FALSE(files.empty()) << "no inputs to check (a corpus or regressions folder is missing)";
  const Mutator mutator(load_dir("corpus/vessels"), Mutator(load_dir("corpus/towlines")).words());
  const auto fields = field_names(mutator.words());
  for (const Input& in : files) {
    Tally tally;
    EXPECT_EQ(check_input(in.text, parse, fields, tally), "") << in.name;
    if (must_parse) {
      EXPECT_EQ(tally.accepted, 1) << in.name << " does not parse";
    }
  }
}

TEST(FuzzShipFile, CorpusParsesAndRoundTrips) {  // fuzz-ship-1
  check_files(load_dir("corpus/vessels"), kParseVessel, true);
  check_files(load_dir("corpus/towlines"), kParseTowline, true);
}

TEST(FuzzShipFile, RegressionInputsKeepTheProperties) {  // fuzz-ship-2
  check_files(load_dir("regressions/vessels"), kParseVessel, false);
  check_files(load_dir("regressions/towlines"), kParseTowline, false);
}

TEST(FuzzShipFile, MutatedVesselFiles) {  // fuzz-ship-3
  run_fuzzer("vessels", "vessels", 20001, 16000, kParseVessel);
}

TEST(FuzzShipFile, MutatedTowlineFiles) {  // fuzz-ship-4
  run_fuzzer("towlines", "towlines", 20002, 40000, kParseTowline);
}

}  // namespace
}  // namespace towdb::fuzz
