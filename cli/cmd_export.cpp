// towdb export --db FILE --format posse-csv|appendix-c [--output FILE]
//   posse-csv   the stable CSV that POSSE imports (column spec: schema/posse-csv.md)
//   appendix-c  the thesis's Appendix C table layout (Desroches 1997), the
//               columns of tests/data/validation/appendix_c_calibration.csv
// Only finished cases (status 'done' with a results row) are exported.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli.hpp"
#include "common/error.hpp"
#include "io/csv.hpp"
#include "output.hpp"
#include "store/database.hpp"

namespace towdb::cli {

namespace {

struct ExportArgs {
  std::string db, format, output;
};

std::string cell(const std::optional<double>& v) { return v ? fmt(*v) : std::string(); }

// Text cells go through the one CSV writer (io/csv.hpp).
constexpr auto& text_cell = io::csv::cell;

// Appendix C vessel labels: "T-ATF 166" -> "T-ATF"; others without spaces ("LHA 1" -> "LHA1").
std::string thesis_label(const std::string& name) {
  std::string compact;
  for (char c : name) {
    if (c != ' ') compact.push_back(c);
  }
  return compact == "T-ATF166" ? "T-ATF" : compact;
}

std::string fixed1(double v) { return fmt(v, 1); }

void export_posse(store::Database& db, std::ostream& os) {
  os << "case_id,tug,tow,line_type,speed_kt,spectrum,wind_kt,hs_ft,tp_s,gamma,heading_deg,length_ft,"
        "mean_tension_lbf,mean_tension_label,days,gumbel_u_kips,gumbel_alpha_per_kip,dynamic_999_kips,"
        "dynamic_99_kips,ci_level,ci_low_kips,ci_high_kips,extreme_999_lbf,breaking_strength_lbf,"
        "above_breaking_strength,slack_fraction,snatch_events_per_day,code_version\n";
  store::Statement st = db.prepare(
      "SELECT c.case_id, c.tug_name, c.tow_name, c.line_type, c.speed_kt, c.spectrum, c.wind_kt, c.hs_ft, c.tp_s, "
      "c.gamma, c.heading_deg, c.length_ft, c.mean_tension_lbf, c.mean_tension_label, c.days, r.gumbel_u_kips, "
      "r.gumbel_alpha_per_kip, r.dynamic_999_kips, r.dynamic_99_kips, r.ci_level, r.ci_low_kips, r.ci_high_kips, "
      "r.breaking_strength_lbf, r.above_breaking_strength, r.slack_fraction, r.snatch_events_per_day, "
      "r.code_version FROM cases c JOIN results r ON r.case_id = c.case_id WHERE c.status = 'done' "
      "ORDER BY c.tug_name, c.tow_name, c.line_type, c.spectrum, c.speed_kt, c.wind_kt, c.hs_ft, c.tp_s, "
      "c.heading_deg, c.length_ft, c.mean_tension_lbf, c.case_id");
  while (st.step()) {
    const double mean = st.column_double(12), dyn = st.column_double(17);
    os << st.column_int(0) << "," << text_cell(st.column_text(1)) << "," << text_cell(st.column_text(2)) << ","
       << st.column_text(3) << "," << fmt(st.column_double(4)) << "," << text_cell(st.column_text(5)) << ","
       << cell(st.column_optional_double(6)) << "," << cell(st.column_optional_double(7)) << ","
       << cell(st.column_optional_double(8)) << "," << cell(st.column_optional_double(9)) << ","
       << fmt(st.column_double(10)) << "," << fmt(st.column_double(11)) << "," << fmt(mean) << ","
       << text_cell(st.column_text(13)) << "," << st.column_int(14) << "," << fmt(st.column_double(15)) << ","
       << fmt(st.column_double(16)) << "," << fmt(dyn) << "," << fmt(st.column_double(18)) << ","
       << fmt(st.column_double(19)) << "," << fmt(st.column_double(20)) << "," << fmt(st.column_double(21)) << ","
       << fmt(mean + 1000.0 * dyn) << "," << fmt(st.column_double(22)) << "," << st.column_int(23) << ","
       << fmt(st.column_double(24)) << "," << fmt(st.column_double(25)) << "," << text_cell(st.column_text(26))
       << "\n";
  }
}

void export_appendix_c(store::Database& db, std::ostream& os) {
  os << "case,tug,tow,speed_kt,wind_kt,heading_deg,length_ft,line,mean_lbf,days,dyn_kips\n";
  store::Statement st = db.prepare(
      "SELECT c.case_id, c.tug_name, c.tow_name, c.speed_kt, c.wind_kt, c.heading_deg, c.length_ft, c.line_type, "
      "c.mean_tension_lbf, c.days, r.dynamic_999_kips FROM cases c JOIN results r ON r.case_id = c.case_id "
      "WHERE c.status = 'done' ORDER BY c.case_id");
  int skipped = 0;
  while (st.step()) {
    const auto wind = st.column_optional_double(4);
    if (!wind) {
      ++skipped;  // Appendix C has wind-defined (Pierson-Moskowitz) seas only
      continue;
    }
    os << st.column_int(0) << "," << thesis_label(st.column_text(1)) << "," << thesis_label(st.column_text(2)) << ","
       << fixed1(st.column_double(3)) << "," << fixed1(*wind) << "," << fixed1(st.column_double(5)) << ","
       << fixed1(st.column_double(6)) << "," << (st.column_text(7) == "wire" ? "w" : "f") << ","
       << fixed1(st.column_double(8)) << "," << st.column_int(9) << "," << fixed1(st.column_double(10)) << "\n";
  }
  if (skipped > 0) {
    std::cerr << "towdb: note: " << skipped
              << " case(s) with Hs-defined seas left out: the Appendix C layout has a wind column only\n";
  }
}

int run_export(const ExportArgs& a) {
  if (!a.output.empty()) check_output_file("--output", a.output);
  store::Database db = store::Database::open(a.db, store::Database::Mode::kReadOnly);
  std::ofstream file;
  if (!a.output.empty()) {
    file.open(a.output, std::ios::binary);
    if (!file) throw InputError("--output " + a.output + ": cannot be written");
  }
  std::ostream& os = a.output.empty() ? std::cout : file;
  if (a.format == "posse-csv") {
    export_posse(db, os);
  } else {
    export_appendix_c(db, os);
  }
  os.flush();
  if (!os) throw StorageError("export: writing " + (a.output.empty() ? std::string("stdout") : a.output) + " failed");
  return 0;
}

}  // namespace

void add_export_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<ExportArgs>();
  CLI::App* e = app.add_subcommand("export", "Export a database as CSV: POSSE import format or thesis Appendix C");
  e->add_option("--db", a->db, "towdb database file (opened read-only)")->required();
  e->add_option("--format", a->format, "posse-csv (column spec in schema/posse-csv.md) or appendix-c")
      ->required()
      ->check(CLI::IsMember({"posse-csv", "appendix-c"}));
  e->add_option("--output", a->output, "Output file (default: stdout)");
  e->callback([&ctx, a] { ctx.action = [a] { return run_export(*a); }; });
}

}  // namespace towdb::cli
