#include "sweep/build/rekey.hpp"

#include <set>

#include "io/file_bytes.hpp"
#include "store/key_bytes.hpp"
#include "sweep/build/writer.hpp"

namespace towdb::sweep {

namespace {

// The hash of the latest stored version of `name` in `table` (vessels or
// towline_components, newest row first) that is not `current_sha256` and holds
// the same TOML document as the file at `path`; empty when none.
std::string earlier_same_toml(store::Database& db, const std::string& table, const std::string& name,
                              const std::string& current_sha256, const std::string& path) {
  store::Statement st = db.prepare("SELECT content_sha256, file_text FROM " + table +
                                   " WHERE name = ? AND content_sha256 <> ? ORDER BY rowid DESC");
  st.bind(1, name).bind(2, current_sha256);
  std::optional<std::string> current_text;
  while (st.step()) {
    if (!current_text) current_text = io::read_file_bytes(path);
    if (io::same_toml_content(st.column_text(1), *current_text)) return st.column_text(0);
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
  for (const io::VesselFile& f : catalog.vessels()) {
    const model::Vessel& v = f.vessel;
    const std::string sha = earlier_same_toml(db, "vessels", v.name, v.content_sha256, v.source_path);
    if (!sha.empty()) vessel_hashes_.emplace(v.name, sha);
  }
  for (const io::TowlineFile& f : catalog.components()) {
    const model::TowlineComponent& c = f.component;
    const std::string sha = earlier_same_toml(db, "towline_components", c.name, c.content_sha256, c.source_path);
    if (!sha.empty()) component_hashes_.emplace(c.name, sha);
  }
  if (!empty()) earlier_catalog_ = catalog.with_content_hashes(vessel_hashes_, component_hashes_);
}

std::optional<StoredCase> EarlierShipFiles::stored_case(const CaseSpec& spec) {
  if (!earlier_catalog_) return {};
  StoredCase s;
  s.earlier = case_keys(spec, *earlier_catalog_, code_version_);
  if (!by_key_) by_key_.emplace(db_.prepare("SELECT case_id, fit_id, inputs_sha256, status FROM cases WHERE case_key = ?"));
  store::Statement& st = *by_key_;
  st.bind_blob(1, store::key_bytes(s.earlier.case_key, "case_key"));
  const bool found = st.step();
  // The case key hashes the inputs hash; checked again so that a stored row
  // that does not match its own key is never adopted.
  const bool adopted = found && st.column_blob(2) == store::key_bytes(s.earlier.inputs_sha256, "inputs_sha256");
  if (adopted) {
    s.case_id = st.column_int(0);
    if (!st.is_null(1)) s.fit_id = st.column_int(1);
    s.status = st.column_text(3);
  }
  st.reset();
  if (!adopted) return {};
  return s;
}

void EarlierShipFiles::rekey(const StoredCase& stored, const CaseKeys& current, std::int64_t tug_vessel_id,
                             std::int64_t tow_vessel_id, const std::string& updated_utc) {
  store::Database& db = db_;
  std::optional<std::int64_t> fit_id = stored.fit_id;
  if (fit_id && *fit_id != current.fit_id) {
    // A sibling case may have moved the fit already (the fit is shared).
    if (!fit_is_stored(db, current.fit_id, current.fit_key)) {
      if (!copy_fit_) {
        const std::string columns = fit_value_columns(db);
        copy_fit_.emplace(db.prepare("INSERT INTO towline_fits (fit_id, fit_key" + columns + ") SELECT ?, ?" +
                                     columns + " FROM towline_fits WHERE fit_id = ?"));
      }
      copy_fit_->bind(1, current.fit_id).bind(2, current.fit_key).bind(3, *fit_id);
      copy_fit_->run();
    }
    fit_id = current.fit_id;
  }
  if (!update_case_) {
    update_case_.emplace(db.prepare(
        "UPDATE cases SET case_key = ?, inputs_sha256 = ?, tug_vessel_id = ?, tow_vessel_id = ?, fit_id = ?, "
        "updated_utc = ? WHERE case_id = ?"));
  }
  store::Statement& st = *update_case_;
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
