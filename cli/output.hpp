// Output helpers for the CLI: aligned text tables and number formatting.
// JSON is written with nlohmann::ordered_json so keys keep their order; every
// key carries its unit suffix.
#ifndef TOWDB_CLI_OUTPUT_HPP
#define TOWDB_CLI_OUTPUT_HPP

#include <ostream>
#include <string>
#include <vector>

namespace towdb::cli {

class TextTable {
 public:
  explicit TextTable(std::vector<std::string> header);
  void add_row(std::vector<std::string> cells);
  void print(std::ostream& os) const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// Fixed-point with `decimals` digits, or shortest round-trip text when decimals < 0.
std::string fmt(double value, int decimals = -1);
// Thousands separators for a rounded integer value: 125000 -> "125,000".
std::string fmt_grouped(double value);
// A word of a shell command line the user can paste: in single quotes when it
// holds a blank or a quote ("LHA 1" -> "'LHA 1'"), else as it is.
std::string shell_word(const std::string& s);

}  // namespace towdb::cli

#endif  // TOWDB_CLI_OUTPUT_HPP
