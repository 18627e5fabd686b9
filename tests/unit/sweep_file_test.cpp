// Sweep files, their expansion into cases, keys and seeds, the calibration
// sweep, serialisation and options validation (generator/sweep).
// Test plan:
//   sweep-file-1  the thesis Table 5-3 grid (db/sweeps/thesis_table_5_3.toml) expands to
//                 2 x 5 x 2 x 3 x 4 x 4 x 3 = 2880 cases minus 12 per skipped condition; labels,
//                 speeds (8.5 kt for AE 26), CG-47 factors 1.0 / 0.6
//   sweep-file-2  the committed calibration sweep reproduces every CSV row (tensions, days)
//   sweep-file-3  bad entries: file:line, key and what is allowed; day_records "all" and
//                 maxima_precision "binary32" by default
//   sweep-file-4  seeds: common random numbers across towlines and tensions (EQ-SWEEP-4);
//                 keys change exactly with their inputs (EQ-SWEEP-5/6)
//   sweep-file-5  serialisation round trip is bit-exact
//   sweep-file-6  options and CaseSpec validation name field, value and range
//   sweep-file-7  a grid's coverage_note becomes one note per tug and tow pair, canonical names; an empty
//                 note is refused
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "sweep/spec/calibration.hpp"
#include "sweep/build/serialize.hpp"
#include "sweep/sweep.hpp"
#include "sweep_test_runner.hpp"
#include "test_support.hpp"

namespace towdb::test {
namespace {

namespace fs = std::filesystem;

const io::ShipCatalog& catalog() {
  static const io::ShipCatalog c = io::ShipCatalog::load(source_dir() / "ships");
  return c;
}

TEST(SweepFile, ThesisTable53GridExpands) {  // sweep-file-1
  const sweep::SweepFile f = sweep::load_sweep(source_dir() / "db/sweeps/thesis_table_5_3.toml");
  const sweep::SweepExpansion e = sweep::expand_sweep(f, catalog());
  // Thesis Table 5-3: 2 tugs x 5 tows x 2 speeds x 3 winds x 4 headings x 4 towlines x 3 tensions.
  constexpr std::size_t kGridCells = 2 * 5 * 2 * 3 * 4 * 4 * 3;
  constexpr std::size_t kCasesPerCondition = 4 * 3;  // towlines x tensions
  EXPECT_EQ(e.cases.size() + kCasesPerCondition * e.skipped.size(), kGridCells);
  std::set<double> ae26_speeds, other_nominal;
  std::map<std::string, int> labels;
  for (const auto& c : e.cases) {
    EXPECT_EQ(c.days, 500);
    EXPECT_LE(c.speed_kt, c.nominal_speed_kt);
    ++labels[c.mean_tension_label];
    if (c.tow == "AE 26") {
      ae26_speeds.insert(c.nominal_speed_kt);
    } else {
      other_nominal.insert(c.nominal_speed_kt);
    }
    // EQ-SWEEP-3: a reduced speed is one where the calculated tension is within the limit.
    if (c.mean_tension_label == "calculated+15%") {
      EXPECT_LE(c.mean_tension_lbf / 1.15, 125000.0 * (1 + 1e-12)) << c.tow << " " << c.speed_kt;
      // Every grid case in a wind sea carries T_calc of its (reduced) speed: mean = factor x T_calc
      // (the column the query's EQ-QUERY-9 axis reads).
      ASSERT_TRUE(c.calculated_mean_tension_lbf.has_value());
      EXPECT_NEAR(c.mean_tension_lbf / *c.calculated_mean_tension_lbf, 1.15, 1e-12);
    }
    if (c.mean_tension_label == "hull+half-propeller") {
      ASSERT_TRUE(c.calculated_mean_tension_lbf.has_value());
      EXPECT_LT(c.mean_tension_lbf, *c.calculated_mean_tension_lbf);
    }
  }
  EXPECT_EQ(ae26_speeds, (std::set<double>{5.0, 8.5}));
  EXPECT_EQ(other_nominal, (std::set<double>{5.0, 9.0}));
  EXPECT_GT(labels["calculated+15%"], 0);
  EXPECT_EQ(labels["calculated+15%"], labels["calculated-15%"]);
  EXPECT_EQ(labels["calculated"], labels["calculated*0.6"]);
  EXPECT_EQ(labels["hull+half-propeller"], labels["calculated+15%"] + labels["calculated"]);
  // For one condition the three tensions are ordered: +15 % > -15 % > hull + half propeller.
  std::map<std::string, std::map<std::string, double>> by_condition;
  for (const auto& c : e.cases) {
    const std::string k = c.tug + c.tow + std::to_string(c.speed_kt) + sweep::sea_text(c.sea) +
                          std::to_string(c.heading_deg) + model::to_string(c.line) + std::to_string(c.length_ft);
    by_condition[k][c.mean_tension_label] = c.mean_tension_lbf;
  }
  for (const auto& [k, t] : by_condition) {
    if (!t.count("calculated+15%")) continue;
    EXPECT_NEAR(t.at("calculated-15%") / t.at("calculated+15%"), 0.85 / 1.15, 1e-12) << k;
    EXPECT_LT(t.at("hull+half-propeller"), t.at("calculated-15%")) << k;
  }
  // Every skipped condition says why.
  for (const auto& s : e.skipped) EXPECT_NE(s.reason.find("exceeds 125000 lbf"), std::string::npos) << s.reason;
}

TEST(SweepFile, CalibrationSweepReproducesTheCsv) {  // sweep-file-2
  // The repository's copy of the thesis table (tests/data/validation/README.md): no skip on a clean clone.
  const fs::path csv = source_dir() / "tests/data/validation/appendix_c_calibration.csv";
  ASSERT_TRUE(fs::exists(csv)) << csv;
  const auto rows = sweep::parse_calibration_csv(read_text(csv), csv.string(), catalog());
  ASSERT_EQ(rows.size(), 240u);  // 241 lines with the header
  // The committed sweep is the tool's output, byte for byte.
  const std::string generated = sweep::calibration_sweep_toml(rows, "appendix_c_calibration.csv");
  EXPECT_EQ(read_text(source_dir() / "db/sweeps/appendix_c_calibration.toml"), generated);
  const sweep::SweepFile f = sweep::parse_sweep(generated, "appendix_c_calibration.toml");
  const sweep::SweepExpansion e = sweep::expand_sweep(f, catalog());
  ASSERT_EQ(e.cases.size(), rows.size());
  EXPECT_TRUE(e.skipped.empty());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const sweep::CaseSpec& c = e.cases[i];
    EXPECT_EQ(c.sweep_label, "appendix-c-" + std::to_string(rows[i].case_number));
    EXPECT_EQ(c.tug, rows[i].tug);
    EXPECT_EQ(c.tow, rows[i].tow);
    EXPECT_EQ(c.speed_kt, rows[i].speed_kt);
    EXPECT_EQ(c.sea.wind_kt.value(), rows[i].wind_kt);
    EXPECT_EQ(c.heading_deg, rows[i].heading_deg);
    EXPECT_EQ(c.length_ft, rows[i].length_ft);
    EXPECT_EQ(model::to_string(c.line), rows[i].line);
    EXPECT_EQ(c.mean_tension_lbf, rows[i].mean_tension_lbf);
    EXPECT_EQ(c.mean_tension_label, "given");
    EXPECT_EQ(c.days, rows[i].days);
  }
  // First data row of the CSV: case 56, T-ATF / LHA1, 5 kt, 20 kt, 0 deg, 2000 ft wire, 95,000 lbf, 10,000 days.
  EXPECT_EQ(rows[0].case_number, 56);
  EXPECT_EQ(rows[0].tug, "T-ATF 166");
  EXPECT_EQ(rows[0].tow, "LHA 1");
  EXPECT_EQ(rows[0].mean_tension_lbf, 95000.0);
  EXPECT_EQ(rows[0].days, 10000);
  EXPECT_EQ(rows[0].dynamic_999_kips, 99.3);
}

void expect_error(const std::string& text, const std::string& expected_part) {
  try {
    const sweep::SweepFile f = sweep::parse_sweep(text, "bad.toml");
    sweep::expand_sweep(f, catalog());
    ADD_FAILURE() << "no error; expected: " << expected_part;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected_part), std::string::npos) << e.what();
  }
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(SweepFile, BadEntriesAreNamedWithFileAndLine) {  // sweep-file-3
  const std::string ok = kSmallSweepToml;
  expect_error(replace(ok, "speeds_kt = [5.0]", "speeds_kt = [5.0]\ncolour = 3"),
               "bad.toml:13: grid[1].colour: unknown key; accepted keys here:");
  expect_error(replace(ok, "length_ft = 2000.0", "length_m = 600.0"), "bad.toml:29: case[1].length_m: unknown key; wrong unit suffix? this table expects 'length_ft'");
  expect_error(replace(ok, "speeds_kt = [5.0]", "speeds_kt = [5.0, 45.0]"),
               "bad.toml:12: grid[1].speeds_kt: element 2 = 45: must be a finite number between 0.1 and 30");
  expect_error(replace(ok, "tows = [\"FFG 7\", \"YRBM\"]", "tows = [\"FFG 7\", \"Titanic\"]"),
               "bad.toml:8: [[grid]] 'small-grid': vessel 'Titanic' is not known");
  expect_error(replace(ok, "tug = \"ARS 50\"\ntow = \"AE 26\"", "tug = \"FFG 7\"\ntow = \"AE 26\""),
               "[[case]] 'explicit-1': 'FFG 7' is not a tug");
  expect_error(replace(ok, "gamma = 3.3\n", ""), "bad.toml:38: case[2].spectrum: a jonswap sea needs gamma");
  expect_error(replace(ok, "headings_deg = [0.0, 180.0]", "headings_deg = [0.0, 0.0]"),
               "gives the same case as bad.toml:8: [[grid]] 'small-grid'");
  expect_error(replace(ok, "format = \"towdb-sweep-1\"", "format = \"towdb-sweep-0\""),
               "format: \"towdb-sweep-0\" is not allowed; expected one of \"towdb-sweep-1\"");
  expect_error(replace(ok, "days = 30\n", ""), "bad.toml:7: grid[1]: days is not set");
  expect_error(replace(ok, "basis = \"calculated\"", "basis = \"guessed\""),
               "grid[1].mean_tensions[1].basis: \"guessed\" is not allowed");
  expect_error(replace(ok, "winds_kt = [20.0]", "seas = [ { spectrum = \"bretschneider\", hs_ft = 8.0, tp_s = 8.0 } ]"),
               "a \"calculated\" mean tension needs a wind");
  expect_error(replace(ok, "format = \"towdb-sweep-1\"", "format = \"towdb-sweep-1\"\nday_records = \"some\""),
               "day_records: \"some\" is not allowed; expected one of \"all\", \"maxima\"");
  expect_error("format = \"towdb-sweep-1\"\ndescription = \"x\"\n", "the sweep has no [[grid]] and no [[case]]");
  expect_error("format = \"towdb-sweep-1\"\ndescription = \"x\"\n[[case]\n", "bad.toml:3:");
  EXPECT_THROW(sweep::load_sweep("/nonexistent/sweep.toml"), InputError);
  // day_records (schema 7): "all" unless the file says "maxima".
  EXPECT_EQ(sweep::parse_sweep(ok, "ok.toml").day_records, sweep::DayRecords::kAll);
  EXPECT_EQ(sweep::parse_sweep(replace(ok, "format = \"towdb-sweep-1\"",
                                       "format = \"towdb-sweep-1\"\nday_records = \"maxima\""),
                               "ok.toml")
                .day_records,
            sweep::DayRecords::kMaxima);
  // maxima_precision (schema 8): binary32 unless the file says binary16.
  EXPECT_EQ(sweep::parse_sweep(ok, "ok.toml").maxima_precision, sweep::MaximaPrecision::kBinary32);
  EXPECT_EQ(sweep::parse_sweep(replace(ok, "format = \"towdb-sweep-1\"",
                                       "format = \"towdb-sweep-1\"\nmaxima_precision = \"binary16\""),
                               "ok.toml")
                .maxima_precision,
            sweep::MaximaPrecision::kBinary16);
  expect_error(replace(ok, "format = \"towdb-sweep-1\"", "format = \"towdb-sweep-1\"\nmaxima_precision = \"half\""),
               "maxima_precision: \"half\" is not allowed; expected one of \"binary16\", \"binary32\"");
}

TEST(SweepFile, SeedsAndKeys) {  // sweep-file-4
  const sweep::SweepFile f = sweep::parse_sweep(kSmallSweepToml, "small.toml");
  const auto cases = sweep::expand_sweep(f, catalog()).cases;
  // EQ-SWEEP-4: one seed per (tug, tow, speed, sea, heading): 2 tows x 2 headings in the grid,
  // shared by the 2 towlines x 2 tensions of each condition.
  std::map<std::string, std::set<std::int64_t>> seeds;
  for (std::size_t i = 0; i < 16; ++i) {
    seeds[cases[i].tow + "/" + std::to_string(cases[i].heading_deg)].insert(cases[i].seed);
  }
  EXPECT_EQ(seeds.size(), 4u);
  std::set<std::int64_t> distinct;
  for (const auto& [k, s] : seeds) {
    EXPECT_EQ(s.size(), 1u) << k;
    distinct.insert(*s.begin());
    EXPECT_GE(*s.begin(), 0);
  }
  EXPECT_EQ(distinct.size(), 4u);
  // The same file expands to the same seeds and keys (determinism).
  const auto again = sweep::expand_sweep(f, catalog()).cases;
  const auto keys = sweep::compute_keys(cases, catalog(), "1.0.0");
  const auto keys_again = sweep::compute_keys(again, catalog(), "1.0.0");
  std::set<std::string> case_keys;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(cases[i].seed, again[i].seed);
    EXPECT_EQ(keys[i].case_key, keys_again[i].case_key);
    case_keys.insert(keys[i].case_key);
  }
  EXPECT_EQ(case_keys.size(), cases.size());
  // A different code version changes case_key and fit_key, not inputs_sha256.
  const auto v2 = sweep::case_keys(cases[0], catalog(), "2.0.0");
  EXPECT_NE(v2.case_key, keys[0].case_key);
  EXPECT_NE(v2.fit_key, keys[0].fit_key);
  EXPECT_EQ(v2.inputs_sha256, keys[0].inputs_sha256);
  // One more day changes the inputs but not the sweep cell (condition_key).
  sweep::CaseSpec longer = cases[0];
  longer.days += 1;
  EXPECT_NE(sweep::case_keys(longer, catalog(), "1.0.0").inputs_sha256, keys[0].inputs_sha256);
  EXPECT_EQ(sweep::condition_key(longer, false), cases[0].condition_key);
  // Cases 0 and 1 differ only in the mean tension: same towline but different fits.
  EXPECT_NE(keys[0].fit_key, keys[1].fit_key);
  EXPECT_EQ(sweep::id_from_key("00000000000000f0123"), 0xF);
  EXPECT_EQ(sweep::id_from_key("fffffffffffffff0"), 0xFFFFFFFFFFFFFFFLL);  // 60 bits, positive
}

TEST(SweepFile, SerialisationIsBitExact) {  // sweep-file-5
  const sweep::SweepFile f = sweep::parse_sweep(kSmallSweepToml, "small.toml");
  const auto cases = sweep::expand_sweep(f, catalog()).cases;
  for (const auto& c : cases) {
    sweep::ByteWriter w;
    sweep::write_spec(w, c);
    sweep::write_outcome(w, closed_form_outcome(c, catalog()));
    const sweep::Bytes bytes = w.take();
    sweep::ByteReader r(bytes);
    const sweep::CaseSpec back = sweep::read_spec(r);
    const sweep::CaseOutcome out = sweep::read_outcome(r);
    EXPECT_TRUE(r.at_end());
    EXPECT_EQ(sweep::case_keys(back, catalog(), "x").inputs_sha256, sweep::case_keys(c, catalog(), "x").inputs_sha256);
    EXPECT_EQ(back.condition_key, c.condition_key);
    EXPECT_EQ(back.calculated_mean_tension_lbf, c.calculated_mean_tension_lbf);
    const sweep::CaseOutcome expected = closed_form_outcome(c, catalog());
    ASSERT_EQ(out.days.size(), expected.days.size());
    for (std::size_t d = 0; d < out.days.size(); ++d) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(out.days[d].max_dynamic_n),
                std::bit_cast<std::uint64_t>(expected.days[d].max_dynamic_n));
    }
    EXPECT_EQ(std::bit_cast<std::uint64_t>(out.statistics.dynamic_999_n),
              std::bit_cast<std::uint64_t>(expected.statistics.dynamic_999_n));
    EXPECT_EQ(out.fit.coefficients_si, expected.fit.coefficients_si);
  }
  sweep::Bytes truncated = {0x53, 1, 0};
  sweep::ByteReader r(truncated);
  EXPECT_THROW(sweep::read_spec(r), StorageError);
}

void expect_input_error(const std::function<void()>& fn, const std::string& part) {
  try {
    fn();
    ADD_FAILURE() << "no error; expected " << part;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(SweepFile, OptionsValidation) {  // sweep-file-6
  sweep::BuildOptions b;
  b.threads = 0;
  expect_input_error([&] { b.validate(); }, "BuildOptions.threads = 0: must be a whole number in [1, 1024]");
  sweep::MeanTensionModel m;
  m.hull_margin = 1.5;
  expect_input_error([&] { m.validate(); }, "MeanTensionModel.hull_margin = 1.5: must be between 0 and 1");
  m = {};
  m.speed_step_kt = 0.0;
  expect_input_error([&] { m.validate(); }, "MeanTensionModel.speed_step_kt = 0: must be between 0.1 and 5");
  const sweep::SweepFile f = sweep::parse_sweep(kSmallSweepToml, "small.toml");
  sweep::CaseSpec c = sweep::expand_sweep(f, catalog()).cases.front();
  c.line = model::LineKind::kChain;
  expect_input_error([&] { c.validate(); }, "CaseSpec.line");
  c.line = model::LineKind::kWire;
  c.days = 0;
  expect_input_error([&] { c.validate(); }, "CaseSpec.days = 0");
  c.days = 10;
  c.sea.hs_ft = 10.0;
  expect_input_error([&] { c.validate(); }, "must be absent for a pierson-moskowitz sea");
  // The production runner is absent until the CLI registers the simulation chain.
  EXPECT_EQ(sweep::default_case_runner(), nullptr);
  sweep::set_default_case_runner(make_test_runner());
  EXPECT_NE(sweep::default_case_runner(), nullptr);
  sweep::set_default_case_runner(nullptr);
  EXPECT_EQ(sweep::default_case_runner(), nullptr);
}

TEST(SweepFile, CoverageNotesNameEveryTugAndTowOfTheGrid) {  // sweep-file-7
  const std::string note = "coverage_note = \"YRBM at 5 kt only: faster it yaws\"\n";
  const std::string text = replace(kSmallSweepToml, "label = \"small-grid\"\n", "label = \"small-grid\"\n" + note);
  const sweep::SweepFile f = sweep::parse_sweep(text, "notes.toml");
  ASSERT_EQ(f.grids.size(), 1u);
  EXPECT_EQ(f.grids[0].coverage_note, "YRBM at 5 kt only: faster it yaws");
  const sweep::SweepExpansion e = sweep::expand_sweep(f, catalog());
  ASSERT_EQ(e.notes.size(), 2u);  // T-ATF 166 with FFG 7 and with YRBM
  EXPECT_EQ(e.notes[0].tug, "T-ATF 166");
  EXPECT_EQ(e.notes[0].tow, "FFG 7");
  EXPECT_EQ(e.notes[1].tow, "YRBM");
  EXPECT_EQ(e.notes[1].sweep_label, "small-grid");
  EXPECT_TRUE(sweep::expand_sweep(sweep::parse_sweep(kSmallSweepToml, "plain.toml"), catalog()).notes.empty());
  expect_error(replace(kSmallSweepToml, "label = \"small-grid\"\n", "label = \"small-grid\"\ncoverage_note = \"\"\n"),
               "grid[1].coverage_note: must not be empty");
}

}  // namespace
}  // namespace towdb::test
