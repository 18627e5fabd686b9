// The strict TOML reading layer shared by every towdb input file (ship,
// towline and sweep files). Physics code never sees text: this layer turns a
// TOML document into typed values and rejects, with file:line, key, value and
// what is allowed:
//   - unknown keys (with a hint when only the unit suffix differs),
//   - missing keys, wrong types, non-finite or out-of-range numbers,
//   - provenance tables without a valid status or a source.
#ifndef TOWDB_IO_STRICT_TOML_HPP
#define TOWDB_IO_STRICT_TOML_HPP

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

namespace towdb::io {

// One number with where it came from, as written in the file (user units).
struct Provenance {
  std::string key;     // dotted key, e.g. "hull.beam_ft"
  std::string value;   // as text, user units
  std::string status;  // S, D, E, F, U or C (see docs/ship-files.md)
  std::string source;
};

// Parses TOML text; a syntax error becomes InputError "path:line:col: message".
toml::table parse_toml(std::string_view text, const std::string& path);

// Reads one TOML table strictly. Every accessor marks its key as used;
// finish() throws for any key that was not asked for.
class StrictTable {
 public:
  StrictTable(const toml::table& table, std::string path, std::string section,
              std::vector<Provenance>* provenance = nullptr);

  bool has(std::string_view key) const;
  // A sub-table (e.g. [hull.stations]); missing -> error unless optional.
  StrictTable table(std::string_view key);
  std::optional<StrictTable> optional_table(std::string_view key);

  std::string string(std::string_view key, const std::set<std::string>& allowed = {});
  std::optional<std::string> optional_string(std::string_view key);
  std::vector<std::string> string_array(std::string_view key);
  bool boolean(std::string_view key);
  double number(std::string_view key, double lo, double hi);
  std::optional<double> optional_number(std::string_view key, double lo, double hi);
  std::int64_t integer(std::string_view key, std::int64_t lo, std::int64_t hi);
  std::vector<double> number_array(std::string_view key, double lo, double hi);

  // Provenance-wrapped scalars: key = { value = ..., status = "S", source = "..." }.
  double sourced_number(std::string_view key, double lo, double hi);
  std::optional<double> optional_sourced_number(std::string_view key, double lo, double hi);
  std::int64_t sourced_integer(std::string_view key, std::int64_t lo, std::int64_t hi);
  std::string sourced_string(std::string_view key, const std::set<std::string>& allowed);
  bool sourced_boolean(std::string_view key);
  // For a table with one status and source (stations, drag).
  void table_provenance(const std::string& what);

  // Throws InputError for the first key (in file order) that was not read.
  void finish() const;

  // "file:line: [section] key" for messages about a key of this table.
  std::string where(std::string_view key) const;
  const std::string& path() const { return path_; }
  const std::string& section() const { return section_; }

 private:
  const toml::node& require(std::string_view key);
  const toml::node* find(std::string_view key);
  const toml::table& sourced(std::string_view key, std::string* status, std::string* source);
  std::string dotted(std::string_view key) const;
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;
  void record(std::string_view key, const std::string& value, const std::string& status,
              const std::string& source);

  const toml::table* table_;
  std::string path_;
  std::string section_;
  std::vector<Provenance>* provenance_;
  std::set<std::string, std::less<>> used_;
};

}  // namespace towdb::io

#endif  // TOWDB_IO_STRICT_TOML_HPP
