#include "io/strict_toml.hpp"

#include <cmath>
#include <sstream>

#include "common/error.hpp"

namespace towdb::io {

namespace {

const std::set<std::string> kStatusCodes = {"S", "D", "E", "F", "U", "C"};

std::string line_of(const toml::node& node) {
  return std::to_string(node.source().begin.line);
}

std::string type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
  }
}

// The unit suffix of a key: the part after the stem, e.g. beam_ft -> (beam, ft).
std::string key_stem(std::string_view key) {
  static const char* kUnits[] = {"_ft2", "_ft", "_lt", "_kt", "_lbf", "_hp", "_m", "_m2", "_kg", "_t",
                                 "_n", "_in", "_s", "_deg", "_rad", "_lb_per_ft", "_kips", "_m_s", "_knots"};
  std::string k(key);
  for (const char* u : kUnits) {
    const std::string suffix(u);
    if (k.size() > suffix.size() && k.compare(k.size() - suffix.size(), suffix.size(), suffix) == 0) {
      return k.substr(0, k.size() - suffix.size());
    }
  }
  return k;
}

// The number of a numeric node. toml++'s value<double>() refuses an integer
// beyond +-2^53 (not exactly a double) with an empty optional, and .value()
// on it threw std::bad_optional_access (exit 1) for "x_ft = [-9223372036854775808]";
// here every integer converts to the nearest double, and the range check of
// the caller names the key (tests/fuzz/regressions/vessels).
double number_of(const toml::node& node) {
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  return node.as_floating_point()->get();
}

}  // namespace

toml::table parse_toml(std::string_view text, const std::string& path) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    throw InputError(path + ": the file is empty");
  }
  try {
    return toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << path << ":" << e.source().begin.line << ":" << e.source().begin.column
       << ": malformed TOML: " << e.description();
    throw InputError(os.str());
  }
}

StrictTable::StrictTable(const toml::table& table, std::string path, std::string section,
                         std::vector<Provenance>* provenance)
    : table_(&table), path_(std::move(path)), section_(std::move(section)), provenance_(provenance) {}

std::string StrictTable::dotted(std::string_view key) const {
  return section_.empty() ? std::string(key) : section_ + "." + std::string(key);
}

std::string StrictTable::where(std::string_view key) const {
  const toml::node* node = table_->get(key);
  const std::string line = node ? line_of(*node) : std::to_string(table_->source().begin.line);
  return path_ + ":" + line + ": " + dotted(key);
}

void StrictTable::fail(std::string_view key, const std::string& message) const {
  throw InputError(where(key) + ": " + message);
}

bool StrictTable::has(std::string_view key) const { return table_->contains(key); }

const toml::node* StrictTable::find(std::string_view key) {
  const toml::node* node = table_->get(key);
  if (node) used_.emplace(key);
  return node;
}

const toml::node& StrictTable::require(std::string_view key) {
  const toml::node* node = find(key);
  if (!node) {
    const std::string stem = key_stem(key);
    for (const auto& [k, other] : *table_) {
      if (k.str() != key && key_stem(k.str()) == stem) {
        throw InputError(path_ + ":" + line_of(other) + ": " + dotted(k.str()) +
                         ": wrong unit suffix; expected '" + std::string(key) +
                         "' (units are part of the key name)");
      }
    }
    throw InputError(path_ + ": " + (section_.empty() ? "top level" : "[" + section_ + "]") +
                     ": missing key '" + std::string(key) + "'");
  }
  return *node;
}

StrictTable StrictTable::table(std::string_view key) {
  const toml::node& node = require(key);
  if (!node.is_table()) fail(key, "is " + type_name(node) + ", expected a table");
  return StrictTable(*node.as_table(), path_, dotted(key), provenance_);
}

std::optional<StrictTable> StrictTable::optional_table(std::string_view key) {
  if (!has(key)) return std::nullopt;
  return table(key);
}

std::string StrictTable::string(std::string_view key, const std::set<std::string>& allowed) {
  const toml::node& node = require(key);
  if (!node.is_string()) fail(key, "is " + type_name(node) + ", expected a string");
  std::string value = node.value<std::string>().value();
  if (!allowed.empty() && !allowed.count(value)) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + ("\"" + a + "\"");
    fail(key, "\"" + value + "\" is not allowed; expected one of " + list);
  }
  return value;
}

std::optional<std::string> StrictTable::optional_string(std::string_view key) {
  if (!has(key)) return std::nullopt;
  return string(key);
}

std::vector<std::string> StrictTable::string_array(std::string_view key) {
  const toml::node& node = require(key);
  if (!node.is_array()) fail(key, "is " + type_name(node) + ", expected an array of strings");
  std::vector<std::string> out;
  for (const toml::node& item : *node.as_array()) {
    if (!item.is_string()) fail(key, "has an element that is " + type_name(item) + ", expected strings");
    out.push_back(item.value<std::string>().value());
  }
  return out;
}

bool StrictTable::boolean(std::string_view key) {
  const toml::node& node = require(key);
  if (!node.is_boolean()) fail(key, "is " + type_name(node) + ", expected true or false");
  return node.value<bool>().value();
}

namespace {
double as_number(const StrictTable& t, std::string_view key, const toml::node& node) {
  if (!node.is_number()) {
    throw InputError(t.where(key) + ": is " + type_name(node) + ", expected a number");
  }
  return number_of(node);
}
void check_range(const StrictTable& t, std::string_view key, double value, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InputError(t.where(key) + " = " + format_value(value) + ": must be a finite number between " +
                     format_value(lo) + " and " + format_value(hi));
  }
}
}  // namespace

double StrictTable::number(std::string_view key, double lo, double hi) {
  const double v = as_number(*this, key, require(key));
  check_range(*this, key, v, lo, hi);
  return v;
}

std::optional<double> StrictTable::optional_number(std::string_view key, double lo, double hi) {
  if (!has(key)) return std::nullopt;
  return number(key, lo, hi);
}

std::int64_t StrictTable::integer(std::string_view key, std::int64_t lo, std::int64_t hi) {
  const toml::node& node = require(key);
  if (!node.is_integer()) fail(key, "is " + type_name(node) + ", expected a whole number");
  const std::int64_t v = node.value<std::int64_t>().value();
  if (v < lo || v > hi) {
    fail(key, "value = " + std::to_string(v) + ": must be between " + std::to_string(lo) + " and " +
                  std::to_string(hi));
  }
  return v;
}

std::vector<double> StrictTable::number_array(std::string_view key, double lo, double hi) {
  const toml::node& node = require(key);
  if (!node.is_array()) fail(key, "is " + type_name(node) + ", expected an array of numbers");
  std::vector<double> out;
  std::size_t index = 0;
  for (const toml::node& item : *node.as_array()) {
    ++index;
    if (!item.is_number()) {
      fail(key, "element " + std::to_string(index) + " is " + type_name(item) + ", expected a number");
    }
    const double v = number_of(item);
    if (!std::isfinite(v) || v < lo || v > hi) {
      fail(key, "element " + std::to_string(index) + " = " + format_value(v) +
                    ": must be a finite number between " + format_value(lo) + " and " + format_value(hi));
    }
    out.push_back(v);
  }
  if (out.empty()) fail(key, "is empty");
  return out;
}

const toml::table& StrictTable::sourced(std::string_view key, std::string* status, std::string* source) {
  const toml::node& node = require(key);
  if (!node.is_table()) {
    fail(key, "is " + type_name(node) +
                  ", expected { value = ..., status = \"S|D|E|F|U|C\", source = \"...\" }");
  }
  const toml::table& t = *node.as_table();
  StrictTable inner(t, path_, dotted(key));
  *status = inner.string("status", kStatusCodes);
  *source = inner.string("source");
  if (source->find_first_not_of(" \t") == std::string::npos) fail(key, "source is empty");
  inner.require("value");
  inner.finish();
  return t;
}

void StrictTable::record(std::string_view key, const std::string& value, const std::string& status,
                         const std::string& source) {
  if (provenance_) provenance_->push_back({dotted(key), value, status, source});
}

double StrictTable::sourced_number(std::string_view key, double lo, double hi) {
  std::string status, source;
  const toml::table& t = sourced(key, &status, &source);
  const toml::node& node = *t.get("value");
  if (!node.is_number()) fail(key, "value is " + type_name(node) + ", expected a number");
  const double v = number_of(node);
  if (!std::isfinite(v) || v < lo || v > hi) {
    fail(key, "value = " + format_value(v) + ": must be a finite number between " + format_value(lo) +
                  " and " + format_value(hi));
  }
  record(key, format_value(v), status, source);
  return v;
}

std::optional<double> StrictTable::optional_sourced_number(std::string_view key, double lo, double hi) {
  if (!has(key)) return std::nullopt;
  return sourced_number(key, lo, hi);
}

std::int64_t StrictTable::sourced_integer(std::string_view key, std::int64_t lo, std::int64_t hi) {
  std::string status, source;
  const toml::table& t = sourced(key, &status, &source);
  const toml::node& node = *t.get("value");
  if (!node.is_integer()) fail(key, "value is " + type_name(node) + ", expected a whole number");
  const std::int64_t v = node.value<std::int64_t>().value();
  if (v < lo || v > hi) {
    fail(key, "value = " + std::to_string(v) + ": must be between " + std::to_string(lo) + " and " +
                  std::to_string(hi));
  }
  record(key, std::to_string(v), status, source);
  return v;
}

std::string StrictTable::sourced_string(std::string_view key, const std::set<std::string>& allowed) {
  std::string status, source;
  const toml::table& t = sourced(key, &status, &source);
  StrictTable inner(t, path_, dotted(key));
  const std::string v = inner.string("value", allowed);
  record(key, v, status, source);
  return v;
}

bool StrictTable::sourced_boolean(std::string_view key) {
  std::string status, source;
  const toml::table& t = sourced(key, &status, &source);
  const toml::node& node = *t.get("value");
  if (!node.is_boolean()) fail(key, "value is " + type_name(node) + ", expected true or false");
  const bool v = node.value<bool>().value();
  record(key, v ? "true" : "false", status, source);
  return v;
}

void StrictTable::table_provenance(const std::string& what) {
  const std::string status = string("status", kStatusCodes);
  const std::string source = string("source");
  if (source.find_first_not_of(" \t") == std::string::npos) fail("source", "is empty");
  if (provenance_) provenance_->push_back({section_, what, status, source});
}

void StrictTable::finish() const {
  // Report in file order: the first unused key by source position.
  const toml::node* first = nullptr;
  std::string first_key;
  for (const auto& [k, node] : *table_) {
    if (used_.count(k.str())) continue;
    if (!first || node.source().begin < first->source().begin) {
      first = &node;
      first_key = std::string(k.str());
    }
  }
  if (!first) return;
  std::string hint;
  const std::string stem = key_stem(first_key);
  for (const auto& u : used_) {
    if (u != first_key && key_stem(u) == stem && stem != first_key) {
      hint = "; wrong unit suffix? this table expects '" + u + "' (units are part of the key name)";
    }
  }
  if (hint.empty()) {
    // A key of the expected family that was never present (missing) is found by
    // the reader itself; here we can only list what the table accepts.
    std::string accepted;
    for (const auto& u : used_) accepted += (accepted.empty() ? "" : ", ") + u;
    hint = accepted.empty() ? "" : "; accepted keys here: " + accepted;
  }
  throw InputError(path_ + ":" + line_of(*first) + ": " + dotted(first_key) + ": unknown key" + hint);
}

}  // namespace towdb::io
