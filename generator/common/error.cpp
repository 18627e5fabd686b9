#include "common/error.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace towdb {

std::string format_value(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::ostringstream os;
  os.precision(15);
  os << value;
  return os.str();
}

void require_input(bool ok, const std::string& field, double value, const std::string& allowed) {
  if (!ok) throw InputError(field + " = " + format_value(value) + ": " + allowed);
}

void require_in_range(const std::string& field, double value, double lo, double hi) {
  require_input(std::isfinite(value) && value >= lo && value <= hi, field, value,
                "must be between " + format_value(lo) + " and " + format_value(hi));
}

void require_positive(const std::string& field, double value) {
  require_input(std::isfinite(value) && value > 0.0, field, value, "must be a finite number > 0");
}

void assertion_failed(const char* expr, const char* file, int line) {
  std::fprintf(stderr, "towdb: internal error: assertion '%s' failed at %s:%d\n", expr, file, line);
  std::abort();
}

}  // namespace towdb
