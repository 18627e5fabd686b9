// Golden checks of the bundled ship data (ships/*.toml) against the generator
// that produced their station tables and against the thesis fragments.
// Test plan:
//   sd-1  every station table is what model::generate_hull_form gives for the
//         file's own particulars (L, B, T, C_b, C_m = sigma at midships, LCB = lcg)
//   sd-2  every station table's volume and centroid match the displacement and lcg
//   sd-3  the T-ATF table's sectional areas agree with the thesis 5D stern stations
//         (tests/data/model/tatf-stern-stations.csv, Desroches 1997 Appendix A)
//   sd-4  every hull resistance curve R(V) = 1/2 rho S V^2 C_T rises with speed
//   sd-5  tow points follow the sign convention (tug aft, tow at the bow, above water)
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/units.hpp"
#include "io/ship_file.hpp"
#include "model/hull_form.hpp"
#include "test_support.hpp"

namespace towdb::model {
namespace {

// The ship files' displacement convention: 35.0 ft^3 of sea water per long ton
// (64.0 lb/ft^3), docs/ship-files.md and docs/ship-data.md section 0.
constexpr double kCubicFeetPerLongTon = 35.0;

const io::ShipCatalog& catalog() {
  static const io::ShipCatalog cat = io::ShipCatalog::load(test::source_dir() / "ships");
  return cat;
}

double midship_area_coefficient(const Hull& h) {
  for (const Station& s : h.stations) {
    if (s.x_m == 0.0) return s.area_coefficient;
  }
  ADD_FAILURE() << "no station at midships";
  return 0.0;
}

// Sectional area A = sigma B T [m^2] interpolated linearly in x.
double section_area_at(const std::vector<Station>& st, double x_m) {
  const auto area = [](const Station& s) { return s.area_coefficient * s.beam_m * s.draft_m; };
  for (std::size_t i = 1; i < st.size(); ++i) {
    if (x_m <= st[i].x_m) {
      const double t = (x_m - st[i - 1].x_m) / (st[i].x_m - st[i - 1].x_m);
      return area(st[i - 1]) + t * (area(st[i]) - area(st[i - 1]));
    }
  }
  return area(st.back());
}

// sd-1
TEST(ShipData, StationTablesAreTheGeneratorsOutput) {
  // EVIDENCE-OF: EQ-HULLFORM-4
  // The files print x to 0.01 ft, beam and draft to 0.001 ft and sigma to
  // 1e-4; half a printed unit plus round-off bounds each difference.
  const double kXAbsTolM = units::ft_to_m(0.006);
  const double kLengthAbsTolM = units::ft_to_m(0.0006);
  constexpr double kSigmaAbsTol = 6e-5;
  ASSERT_EQ(catalog().vessels().size(), 7u);
  for (const io::VesselFile& vf : catalog().vessels()) {
    const Hull& h = vf.vessel.hull;
    SCOPED_TRACE(vf.vessel.name);
    HullFormParticulars p;
    p.length_pp_m = h.length_pp_m;
    p.beam_m = h.beam_m;
    p.draft_m = h.draft_m;
    const double lbt_ft3 = units::m_to_ft(h.length_pp_m) * units::m_to_ft(h.beam_m) * units::m_to_ft(h.draft_m);
    p.block_coefficient = units::kg_to_long_tons(h.displacement_kg) * kCubicFeetPerLongTon / lbt_ft3;
    p.midship_coefficient = midship_area_coefficient(h);
    p.lcb_m = h.lcg_m;
    const HullForm form = generate_hull_form(p);
    ASSERT_EQ(form.stations.size(), h.stations.size());
    for (std::size_t i = 0; i < h.stations.size(); ++i) {
      EXPECT_ABS_CLOSE(h.stations[i].x_m, form.stations[i].x_m, kXAbsTolM) << "station " << i;
      EXPECT_ABS_CLOSE(h.stations[i].beam_m, form.stations[i].beam_m, kLengthAbsTolM) << "station " << i;
      EXPECT_ABS_CLOSE(h.stations[i].draft_m, form.stations[i].draft_m, kLengthAbsTolM) << "station " << i;
      EXPECT_ABS_CLOSE(h.stations[i].area_coefficient, form.stations[i].area_coefficient, kSigmaAbsTol)
          << "station " << i;
    }
  }
}

// sd-2
TEST(ShipData, StationVolumeAndCentroidMatchDisplacementAndLcg) {
  // Hull::displacement_volume_m3 uses kRhoSeawater_kg_m3 = 1.9905 slug/ft^3
  // (64.04 lb/ft^3), the files 64.0 lb/ft^3: 0.07 % apart, plus printing
  // round-off 1e-4 -> 0.1 %. (The loader itself allows 5 %.)
  constexpr double kVolumeRelTol = 1e-3;
  // LCB to the printed precision of the tables: 0.02 ft on ships of 150-780 ft.
  const double kLcbAbsTolM = units::ft_to_m(0.02);
  for (const io::VesselFile& vf : catalog().vessels()) {
    const Hull& h = vf.vessel.hull;
    SCOPED_TRACE(vf.vessel.name);
    EXPECT_REL_CLOSE(station_volume_m3(h.stations), h.displacement_volume_m3(), kVolumeRelTol);
    EXPECT_ABS_CLOSE(station_lcb_m(h.stations), h.lcg_m, kLcbAbsTolM);
  }
}

// sd-3
TEST(ShipData, TatfSectionalAreasAgreeWithThesisSternStations) {
  std::ifstream in(test::source_dir() / "tests/data/model/tatf-stern-stations.csv");
  ASSERT_TRUE(in) << "tests/data/model/tatf-stern-stations.csv";
  struct Row {
    double x_ft, beam_ft, draft_ft, sigma;
  };
  std::vector<Row> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'x') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream ls(line);
    Row r{};
    ls >> r.x_ft >> r.beam_ft >> r.draft_ft >> r.sigma;
    ASSERT_FALSE(ls.fail()) << line;
    rows.push_back(r);
  }
  ASSERT_EQ(rows.size(), 4u);
  const Vessel& tatf = catalog().vessel("T-ATF 166").vessel;
  // The generated afterbody (power law, constant draft) has to carry the
  // thesis section areas within 10 % where the hull is still deep
  // (x >= -88 ft: measured -1 %, +4 %, -1 %). At -97.5 ft the thesis stern is
  // cut up but keeps 37 ft of beam (86 ft^2); the pointed power-law end gives
  // about 49 ft^2 there: a known limit of the method, not asserted.
  constexpr double kSectionAreaRelTol = 0.10;
  for (const Row& r : rows) {
    if (r.x_ft < -90.0) continue;
    const double thesis_m2 = units::ft2_to_m2(r.beam_ft * r.draft_ft * r.sigma);
    EXPECT_REL_CLOSE(section_area_at(tatf.hull.stations, units::ft_to_m(r.x_ft)), thesis_m2, kSectionAreaRelTol)
        << "x = " << r.x_ft << " ft";
  }
}

// sd-4
TEST(ShipData, HullResistanceRisesWithSpeed) {
  // A falling R(V) would give negative hull surge damping dR/dV (EQ-PROPULSION-2, docs/physics.md 4.1).
  for (const io::VesselFile& vf : catalog().vessels()) {
    const Vessel& v = vf.vessel;
    SCOPED_TRACE(v.name);
    double previous_n = 0.0;
    const double top_kt = units::m_s_to_kt(v.drag.speed_m_s.back());
    for (double kt = 0.5; kt <= top_kt + 1e-9; kt += 0.5) {
      const double r_n = v.hull_resistance_n(units::kt_to_m_s(kt));
      EXPECT_GT(r_n, previous_n) << kt << " kt";
      previous_n = r_n;
    }
  }
}

// sd-5
TEST(ShipData, TowPointsFollowTheSignConvention) {
  for (const io::VesselFile& vf : catalog().vessels()) {
    const Vessel& v = vf.vessel;
    SCOPED_TRACE(v.name);
    if (v.role == VesselRole::kTug) {
      EXPECT_LT(v.tow_point.x_m, 0.0);  // aft of midships
    } else {
      EXPECT_GT(v.tow_point.x_m, 0.4 * v.hull.length_pp_m);  // at the bow
    }
    // On the hull: at most the whole overhang LOA - L_pp beyond a perpendicular.
    EXPECT_LE(std::abs(v.tow_point.x_m), v.hull.length_overall_m - 0.5 * v.hull.length_pp_m);
    EXPECT_GT(v.tow_point.z_m, 0.0);  // above the waterline
  }
}

}  // namespace
}  // namespace towdb::model
