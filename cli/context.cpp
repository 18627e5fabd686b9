#include <charconv>
#include <cmath>
#include <filesystem>
#include <system_error>
#include <string>

#include "cli.hpp"
#include "common/error.hpp"

namespace towdb::cli {

io::ShipCatalog load_catalog(const Context& ctx) {
  return io::ShipCatalog::load(ctx.ships_dir.empty() ? io::default_ships_dir()
                                                      : std::filesystem::path(ctx.ships_dir));
}

bool parse_number(const std::string& text, double* out) {
  const char* b = text.data();
  const char* e = b + text.size();
  const auto r = std::from_chars(b, e, *out);
  return r.ec == std::errc() && r.ptr == e && std::isfinite(*out);
}

CLI::Validator number_in(double lo, double hi, bool lo_open, bool hi_open) {
  const std::string desc = std::string(lo_open ? "(" : "[") + format_value(lo) + ", " + format_value(hi) +
                           (hi_open ? ")" : "]");
  return CLI::Validator(
      [=](std::string& s) -> std::string {
        double v = 0;
        if (!parse_number(s, &v)) return "'" + s + "' is not a finite number";
        const bool ok = (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
        return ok ? std::string() : "value " + s + " not in " + desc;
      },
      "NUMBER in " + desc, "number_in");
}

void check_output_file(const std::string& flag, const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError(flag + " = '': give a file name");
  const fs::path p(path);
  std::error_code ec;
  if (fs::is_directory(p, ec)) throw InputError(flag + " = " + path + ": is a directory, expected a file name");
  const fs::path parent = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec)) {
    throw InputError(flag + " = " + path + ": the directory " + parent.string() + " does not exist");
  }
}

void check_output_dir(const std::string& flag, const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError(flag + " = '': give a directory");
  const fs::path p(path);
  std::error_code ec;
  if (fs::exists(p, ec) && !fs::is_directory(p, ec)) {
    throw InputError(flag + " = " + path + ": is a file, expected a directory (existing or new)");
  }
  fs::path dir = p.lexically_normal();
  if (!dir.has_filename() && dir.has_parent_path()) dir = dir.parent_path();  // "out/" names "out"
  const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
  if (!fs::exists(p, ec) && !fs::is_directory(parent, ec)) {
    throw InputError(flag + " = " + path + ": its parent directory " + parent.string() + " does not exist");
  }
}

CLI::Validator unsigned_integer() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        const bool digits = !s.empty() && s.size() <= 19 && s.find_first_not_of("0123456789") == std::string::npos;
        return digits ? std::string() : "'" + s + "' is not a whole number from 0 to 9999999999999999999";
      },
      "UINT", "unsigned_integer");
}

}  // namespace towdb::cli
