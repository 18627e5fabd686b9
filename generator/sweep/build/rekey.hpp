// Cases whose ship or towline files changed in comments or layout only.
//
// EQ-SWEEP-6's keys hash each ship and towline file's bytes, so an edited
// comment in ships/ changes the keys of every case that uses the file, and a
// build would recompute those cases although nothing they compute from has
// changed. EarlierShipFiles finds, for each vessel and towline component of
// the catalog whose file is not stored under its current hash, the latest
// stored version of the same name whose text is the same TOML document
// (io::same_toml_content: the same tables, keys and values; comments, blank
// lines, layout and key order aside). A case of the sweep whose keys, computed
// with those stored hashes (everything else as now: inputs, seed, condition,
// code version), are a stored case's keys is that case, computed from the
// same numbers: the build moves it to the current keys (rekey_case) instead
// of recomputing it. Its results, daily maxima and towline fit stay as stored.
//
// A case computed while only some of today's edited files had their earlier
// text (edits spread over several builds) is not recognised and is recomputed.
#ifndef TOWDB_SWEEP_REKEY_HPP
#define TOWDB_SWEEP_REKEY_HPP

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/ship_file.hpp"
#include "store/database.hpp"
#include "sweep/spec/case.hpp"
#include "sweep/spec/keys.hpp"

namespace towdb::sweep {

// A stored case that a sweep case is, under the earlier file texts.
struct StoredCase {
  std::int64_t case_id = 0;
  std::optional<std::int64_t> fit_id;  // its towline fit (none while not done)
  std::string status;                  // cases.status
  CaseKeys earlier;                    // its keys, as stored
};

class EarlierShipFiles {
 public:
  // Reads the stored file versions (tables vessels, towline_components).
  EarlierShipFiles(store::Database& db, const io::ShipCatalog& catalog, const std::string& code_version);

  // No file of the catalog changed in layout only: nothing to re-key.
  bool empty() const { return vessel_hashes_.empty() && component_hashes_.empty(); }
  // The stored case `spec` is under the earlier texts, if any.
  std::optional<StoredCase> stored_case(const CaseSpec& spec);
  // Moves a stored case to its current keys and vessel rows, and its towline
  // fit to the fit's current key (a copy of the fit row; see
  // drop_unused_fits). Call inside the registration's transaction.
  void rekey(const StoredCase& stored, const CaseKeys& current, std::int64_t tug_vessel_id,
             std::int64_t tow_vessel_id, const std::string& updated_utc);

 private:
  store::Database& db_;
  std::string code_version_;
  // Canonical name -> the stored content_sha256 of its earlier, same-TOML text.
  std::map<std::string, std::string> vessel_hashes_, component_hashes_;
  std::optional<io::ShipCatalog> earlier_catalog_;
  // Statements prepared at first use (one registration asks for every case).
  std::optional<store::Statement> by_key_, copy_fit_, update_case_;
};

// Deletes the fits among `fit_ids` that no case refers to any more.
void drop_unused_fits(store::Database& db, const std::vector<std::int64_t>& fit_ids);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_REKEY_HPP
