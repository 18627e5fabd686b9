// The calibration sweep: every case of the thesis's Appendix C calibration
// table (tests/data/validation/appendix_c_calibration.csv, columns
// case,tug,tow,speed_kt,wind_kt,heading_deg,length_ft,line,mean_lbf,days,dyn_kips)
// as one [[case]] of a sweep file, with its given mean tension and days.
// The thesis's dynamic tension (dyn_kips) is kept as a comment next to each
// case, for the validation that compares the database with it.
#ifndef TOWDB_SWEEP_CALIBRATION_HPP
#define TOWDB_SWEEP_CALIBRATION_HPP

#include <string>
#include <string_view>
#include <vector>

#include "io/ship_file.hpp"

namespace towdb::sweep {

struct CalibrationRow {
  int case_number = 0;        // thesis run number
  std::string tug;            // canonical catalog name
  std::string tow;            // canonical catalog name
  double speed_kt = 0.0;
  double wind_kt = 0.0;       // Pierson-Moskowitz sea
  double heading_deg = 0.0;   // 0 following, 180 head
  double length_ft = 0.0;
  std::string line;           // "wire" or "fiber"
  double mean_tension_lbf = 0.0;
  int days = 0;
  double dynamic_999_kips = 0.0;  // the thesis's result
};

// Strict CSV reader: the header must be exactly the one above; every field
// must parse completely. Names are resolved through the catalog (T-ATF,
// ARS50, LHA1, AE26, FFG7, YRBM; line w/f). Throws InputError "path:line: ...".
std::vector<CalibrationRow> parse_calibration_csv(std::string_view text, const std::string& path,
                                                  const io::ShipCatalog& catalog);

// The sweep file text (format towdb-sweep-1) with one [[case]] per row, label
// "appendix-c-<case>", mean tension label "given".
std::string calibration_sweep_toml(const std::vector<CalibrationRow>& rows, const std::string& source_name);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_CALIBRATION_HPP
