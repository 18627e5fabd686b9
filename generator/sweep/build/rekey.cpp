#include "sweep/build/rekey.hpp"

#include <set>

#include "common/error.hpp"
#include "io/file_bytes.hpp"
#include "store/key_bytes.hpp"

namespace towdb::sweep {

namespace {

// The latest stored version of `name` in `table` (vessels or
// towline_components, newest row first) that is not `current_sha256` and holds
// the same TOML document as `current_text`; empty when none.
std::string earlier_same_toml(store::Database& db, const char* sql, const std::string& name,
                              const std::string& current_sha256, const std::string& current_text) {
  store::Statement st = db.prepare(sql);
  st.bind(1, name).bind(2, current_sha256);
  while (st.step()) {
    if (io::same_toml_content(st.column_text(1), current_text)) return st.column_text(0);
  }
  return {};
}

// Columns of towline_fits other than its two keys, in table order.
std::string fit_value_columns(store::Database& db) {
  store::Statement st = db.prepare("SELECT name FROM pragma_table_info('towline_fits') ORDER BY cid");
  std::string columns;
  while (st.step()) {
    const std::string name = st.column_text(0);
    if (name == "fit_id" || name == "fit_key") continue;
    columns += ", " + name;
  }
  return columns;
}

}  // namespace

EarlierShipFiles::EarlierShipFiles(store::Database& db, const io::ShipCatalog& catalog,
                                   const std::string& code_version)
    : db_(db), code_version_(code_version) {
  for (const io::VesselFile& v : catalog.vessels()) {
    const std::string sha = earlier_same_toml(
        db, "SELECT content_sha256, file_text FROM vessels WHERE name = ? AND content_sha256 <> ? "
            "ORDER BY vessel_id DESC",
        v.vessel.name, v.vessel.content_sha256, io::read_file_bytes(v.vessel.source_path));
    if (!sha.empty()) vessel_hashes_.emplace(v.vessel.name, sha);
  }
  for (const io::TowlineFile& c : catalog.components()) {
    const std::string sha = earlier_same_toml(
        db, "SELECT content_sha256, file_text FROM towline_components WHERE name = ? AND content_sha256 <> ? "
            "ORDER BY component_id DESC",
        c.component.name, c.component.content_sha256, io::read_file_bytes(c.component.source_path));
    if (!sha.empty()) component_hashes_.emplace(c.component.name, sha);
  }
  if (!empty()) earlier_catalog_ = catalog.with_content_hashes(vessel_hashes_, component_hashes_);
}

std::optional<StoredCase> EarlierShipFiles::stored_case(const CaseSpec& spec) {
  if (!earlier_catalog_) return {};
  StoredCase s;
  s.earlier = case_keys(spec, *earlier_catalog_, code_version_);
  store::Statement st = db_.prepare("SELECT case_id, fit_id, inputs_sha256, status FROM cases WHERE case_key = ?");
  st.bind_blob(1, store::key_bytes(s.earlier.case_key, "case_key"));
  if (!st.step()) return {};
  // The case key hashes the inputs hash; checked again so that a stored row
  // that does not match its own key is never adopted.
  if (st.column_blob(2) != store::key_bytes(s.earlier.inputs_sha256, "inputs_sha256")) return {};
  s.case_id = st.column_int(0);
  if (!st.is_null(1)) s.fit_id = st.column_int(1);
  s.status = st.column_text(3);
  return s;
}

void EarlierShipFiles::rekey(const StoredCase& stored, const CaseKeys& current, std::int64_t tug_vessel_id,
                             std::int64_t tow_vessel_id, const std::string& updated_utc) {
  store::Database& db = db_;
  std::optional<std::int64_t> fit_id = stored.fit_id;
  if (fit_id && *fit_id != current.fit_id) {
    if (fit_columns_.empty()) fit_columns_ = fit_value_columns(db);
    const std::string& columns = fit_columns_;
    store::Statement copy = db.prepare("INSERT OR IGNORE INTO towline_fits (fit_id, fit_key" + columns +
                                       ") SELECT ?, ?" + columns + " FROM towline_fits WHERE fit_id = ?");
    copy.bind(1, current.fit_id).bind(2, current.fit_key).bind(3, *fit_id);
    copy.run();
    store::Statement check = db.prepare("SELECT fit_key FROM towline_fits WHERE fit_id = ?");
    check.bind(1, current.fit_id);
    if (!check.step() || check.column_text(0) != current.fit_key) {
      throw StorageError("towline_fits: fit_id " + std::to_string(current.fit_id) + " of key " + current.fit_key +
                         " is taken by another key (60-bit id collision)");
    }
    fit_id = current.fit_id;
  }
  store::Statement st = db.prepare(
      "UPDATE cases SET case_key = ?, inputs_sha256 = ?, tug_vessel_id = ?, tow_vessel_id = ?, fit_id = ?, "
      "updated_utc = ? WHERE case_id = ?");
  st.bind_blob(1, store::key_bytes(current.case_key, "case_key"))
      .bind_blob(2, store::key_bytes(current.inputs_sha256, "inputs_sha256"))
      .bind(3, tug_vessel_id)
      .bind(4, tow_vessel_id);
  if (fit_id) {
    st.bind(5, *fit_id);
  } else {
    st.bind_null(5);
  }
  st.bind(6, updated_utc).bind(7, stored.case_id);
  st.run();
}

void drop_unused_fits(store::Database& db, const std::vector<std::int64_t>& fit_ids) {
  if (fit_ids.empty()) return;
  std::set<std::int64_t> used;
  store::Statement in_use = db.prepare("SELECT DISTINCT fit_id FROM cases WHERE fit_id IS NOT NULL");
  while (in_use.step()) used.insert(in_use.column_int(0));
  store::Statement drop = db.prepare("DELETE FROM towline_fits WHERE fit_id = ?");
  for (const std::int64_t id : std::set<std::int64_t>(fit_ids.begin(), fit_ids.end())) {
    if (used.count(id) != 0) continue;
    drop.bind(1, id);
    drop.run();
  }
}

}  // namespace towdb::sweep
