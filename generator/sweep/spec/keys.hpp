// Keys, seeds and canonical text of a case (EQ-SWEEP-4..7 in sweep/sweep.hpp).
// Every number enters a hash as its shortest round-trip decimal text, so a
// key changes exactly when an input's bits change.
#ifndef TOWDB_SWEEP_KEYS_HPP
#define TOWDB_SWEEP_KEYS_HPP

#include <cstdint>
#include <string>

#include "io/ship_file.hpp"
#include "sweep/spec/case.hpp"

namespace towdb::sweep {

// Shortest decimal text that reads back to the same double ("5", "1.15").
std::string canonical_number(double value);

// Canonical one-line text of a sea ("pierson-moskowitz wind_kt=20",
// "jonswap hs_ft=10 tp_s=9 gamma=3.3 swell=4/12/90"); used in keys and listings.
std::string sea_text(const SeaSpec& sea);

// EQ-SWEEP-4. Non-negative, < 2^63.
std::int64_t case_seed(std::int64_t base_seed, const CaseSpec& spec);

// EQ-SWEEP-5. `include_tension` adds the mean tension (for "given" tensions,
// whose label alone does not tell two cases apart).
std::string condition_key(const CaseSpec& spec, bool include_tension);

struct CaseKeys {
  std::string inputs_sha256;  // EQ-SWEEP-6
  std::string case_key;       // EQ-SWEEP-6
  std::string fit_key;        // EQ-SWEEP-6
  std::int64_t fit_id = 0;    // EQ-SWEEP-7
  std::string tug_sha256;     // the tug's ship file
  std::string tow_sha256;     // the tow's ship file
};

// EQ-SWEEP-6/7. Looks the vessels and towline components up in `catalog`
// (InputError for unknown names or a tug without that hawser).
CaseKeys case_keys(const CaseSpec& spec, const io::ShipCatalog& catalog, const std::string& code_version);

// EQ-SWEEP-7: the first 15 hex digits (60 bits) of a hex key as an integer.
std::int64_t id_from_key(const std::string& hex_key);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_KEYS_HPP
