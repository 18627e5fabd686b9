// Towlines used by the towline-module tests: the thesis T-ATF chain pendant
// and wire (Desroches 1997, Appendix A, t-atf.win) and an estimated nylon
// hawser, read from tests/data/towline/thesis_towline_components.csv (the
// sources are cited there). The thesis database's towline "length" is the
// hawser length; the 90 ft chain pendant is added at the tow end
// (segments tug -> tow, as model::Towline requires).
#ifndef TOWDB_TESTS_SUPPORT_TOWLINE_TEST_LINES_HPP
#define TOWDB_TESTS_SUPPORT_TOWLINE_TEST_LINES_HPP

#include <charconv>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "model/towline.hpp"
#include "test_support.hpp"
#include "towline/catenary.hpp"

namespace towdb::test {

// Parses one number with full consumption (throws on anything else).
inline double parse_number(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  if (result.ec != std::errc{} || result.ptr != end) throw std::runtime_error("not a number: '" + text + "'");
  return value;
}

// The component named `name` from thesis_towline_components.csv, in SI.
inline model::TowlineComponent thesis_component(const std::string& name) {
  const auto path = source_dir() / "tests/data/towline/thesis_towline_components.csv";
  for (const auto& f : read_csv_rows(path)) {
    if (f.size() != 9) {
      throw std::runtime_error("bad row in " + path.string() + " (" + std::to_string(f.size()) + " cells, 9 expected)");
    }
    if (f[0] != name) continue;
    model::TowlineComponent c;
    c.name = f[0];
    c.kind = f[1] == "chain" ? model::LineKind::kChain
             : f[1] == "wire" ? model::LineKind::kWire
                              : model::LineKind::kFiber;
    c.ea_n = units::lbf_to_n(parse_number(f[2]));
    c.hydrodynamic_diameter_m = units::ft_to_m(parse_number(f[3]));
    c.mass_per_length_kg_m = units::lb_per_ft_to_kg_per_m(parse_number(f[4]));
    c.weight_in_water_n_m = units::lbf_per_ft_to_n_per_m(parse_number(f[5]));
    c.breaking_strength_n = units::lbf_to_n(parse_number(f[6]));
    c.drag_coefficient_normal = parse_number(f[7]);
    c.added_mass_coefficient = parse_number(f[8]);
    return c;
  }
  throw std::runtime_error("no component '" + name + "' in " + path.string());
}

// Hawser ("wire" or "nylon") of `hawser_length_ft`, then the 90 ft chain.
inline model::Towline thesis_towline(const std::string& hawser, double hawser_length_ft) {
  model::Towline t;
  t.segments.push_back({thesis_component(hawser), units::ft_to_m(hawser_length_ft)});
  t.segments.push_back({thesis_component("chain"), units::ft_to_m(90.0)});
  return t;
}

// Tow points: T-ATF 6 ft above the waterline (thesis t-atf.bld "30.0 6.0"),
// tow bow fitting 25 ft (the brief's 20-30 ft).
inline towline::TowPoints thesis_tow_points() {
  return {units::ft_to_m(6.0), units::ft_to_m(25.0)};
}

}  // namespace towdb::test

#endif  // TOWDB_TESTS_SUPPORT_TOWLINE_TEST_LINES_HPP
