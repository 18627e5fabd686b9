#include "sweep/spec/keys.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

#include "common/error.hpp"
#include "common/units.hpp"

namespace towdb::sweep {

namespace {

// Hex digits of a key read into an id: 15 hex digits = 60 bits, always a
// positive int64 (SQLite INTEGER PRIMARY KEY).
constexpr std::size_t kIdHexDigits = 15;

std::string hawser_towline_text(const CaseSpec& spec, const io::ShipCatalog& catalog) {
  const model::Vessel& tug = catalog.vessel(spec.tug).vessel;
  const model::Towline line = catalog.towline(tug, spec.line, spec.length_m());
  std::string text;
  for (const model::TowlineSegment& s : line.segments) {
    text += s.component.name + "@" + s.component.content_sha256 + ":" + canonical_number(s.length_m) + ";";
  }
  return text;
}

}  // namespace

std::string canonical_number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  TOWDB_ASSERT(result.ec == std::errc());
  return std::string(buffer, result.ptr);
}

std::string sea_text(const SeaSpec& sea) {
  std::string t = to_string(sea.kind);
  if (sea.wind_kt) t += " wind_kt=" + canonical_number(*sea.wind_kt);
  if (sea.hs_ft) t += " hs_ft=" + canonical_number(*sea.hs_ft);
  if (sea.tp_s) t += " tp_s=" + canonical_number(*sea.tp_s);
  if (sea.gamma) t += " gamma=" + canonical_number(*sea.gamma);
  if (sea.swell) {
    t += " swell_hs_ft=" + canonical_number(sea.swell->hs_ft) + " swell_tp_s=" + canonical_number(sea.swell->tp_s) +
         " swell_heading_deg=" + canonical_number(sea.swell->heading_deg);
  }
  return t;
}

std::int64_t case_seed(std::int64_t base_seed, const CaseSpec& spec) {
  const std::string text = "seed|" + std::to_string(base_seed) + "|" + spec.tug + "|" + spec.tow + "|" +
                           canonical_number(spec.speed_kt) + "|" + sea_text(spec.sea) + "|" +
                           canonical_number(spec.heading_deg);
  // 15 hex digits = 60 bits, < 2^63 (EQ-SWEEP-4).
  return id_from_key(io::sha256_hex(text));
}

std::string condition_key(const CaseSpec& spec, bool include_tension) {
  std::string text = "condition|" + spec.sweep_label + "|" + spec.tug + "|" + spec.tow + "|" +
                     canonical_number(spec.nominal_speed_kt) + "|" + sea_text(spec.sea) + "|" +
                     canonical_number(spec.heading_deg) + "|" + model::to_string(spec.line) + "|" +
                     canonical_number(spec.length_ft) + "|" + spec.mean_tension_label;
  if (include_tension) text += "|" + canonical_number(spec.mean_tension_lbf);
  return io::sha256_hex(text);  // EQ-SWEEP-5
}

CaseKeys case_keys(const CaseSpec& spec, const io::ShipCatalog& catalog, const std::string& code_version) {
  CaseKeys k;
  k.tug_sha256 = catalog.vessel(spec.tug).vessel.content_sha256;
  k.tow_sha256 = catalog.vessel(spec.tow).vessel.content_sha256;
  const std::string towline = hawser_towline_text(spec, catalog);
  const std::string inputs = "inputs|tug=" + spec.tug + "@" + k.tug_sha256 + "|tow=" + spec.tow + "@" +
                             k.tow_sha256 + "|towline=" + towline + "|speed_kt=" + canonical_number(spec.speed_kt) +
                             "|sea=" + sea_text(spec.sea) + "|heading_deg=" + canonical_number(spec.heading_deg) +
                             "|line=" + model::to_string(spec.line) + "|length_ft=" +
                             canonical_number(spec.length_ft) + "|mean_tension_lbf=" +
                             canonical_number(spec.mean_tension_lbf) + "|days=" + std::to_string(spec.days) +
                             "|seed=" + std::to_string(spec.seed);
  k.inputs_sha256 = io::sha256_hex(inputs);
  k.case_key = io::sha256_hex("case|" + k.inputs_sha256 + "|" + spec.condition_key + "|" + code_version);
  k.fit_key = io::sha256_hex("fit|tug=" + k.tug_sha256 + "|tow=" + k.tow_sha256 + "|towline=" + towline +
                             "|line=" + model::to_string(spec.line) + "|length_ft=" +
                             canonical_number(spec.length_ft) + "|mean_tension_lbf=" +
                             canonical_number(spec.mean_tension_lbf) + "|" + code_version);
  k.fit_id = id_from_key(k.fit_key);
  return k;
}

std::int64_t id_from_key(const std::string& hex_key) {
  TOWDB_ASSERT(hex_key.size() >= kIdHexDigits);
  std::uint64_t value = 0;
  const auto result = std::from_chars(hex_key.data(), hex_key.data() + kIdHexDigits, value, 16);
  TOWDB_ASSERT(result.ec == std::errc() && result.ptr == hex_key.data() + kIdHexDigits);
  return static_cast<std::int64_t>(value);
}

}  // namespace towdb::sweep
