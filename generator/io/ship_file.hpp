// Ship and towline files: ships/*.toml and ships/towlines/*.toml, in the format
// of docs/ship-files.md. The only place towdb reads them; the result is the SI
// model structs of generator/model plus the provenance of every number.
#ifndef TOWDB_IO_SHIP_FILE_HPP
#define TOWDB_IO_SHIP_FILE_HPP

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "io/strict_toml.hpp"
#include "model/towline.hpp"
#include "model/vessel.hpp"

namespace towdb::io {

struct VesselFile {
  model::Vessel vessel;
  std::string description;
  std::vector<Provenance> provenance;  // every number as written, with status and source
};

struct TowlineFile {
  model::TowlineComponent component;
  std::string description;
  std::vector<Provenance> provenance;
};

// Parse from text (`path` is used in messages and recorded as the source path).
VesselFile parse_vessel(std::string_view text, const std::string& path);
TowlineFile parse_towline_component(std::string_view text, const std::string& path);
// Read and parse a file; a missing or unreadable file is an InputError.
VesselFile load_vessel(const std::filesystem::path& path);
TowlineFile load_towline_component(const std::filesystem::path& path);

// Lookup key of a vessel or component name: lower case, only letters and digits
// ("T-ATF 166" -> "tatf166", "ffg-7" -> "ffg7").
std::string normalize_name(std::string_view name);

// Lower-case hex SHA-256 of bytes.
std::string sha256_hex(std::string_view bytes);

// Whether two ship or towline file texts hold the same TOML document: the same
// tables, keys and values (comments, blank lines, layout and key order aside).
// False when either text is not valid TOML.
bool same_toml_content(std::string_view a, std::string_view b);

// The default ships directory: $TOWDB_SHIPS_DIR, else <prefix>/share/towdb/ships
// next to an installed executable, else the source tree's ships/.
std::filesystem::path default_ships_dir();

// All vessels and towline components of a ships directory, loaded and
// cross-checked once (duplicate names, tugs naming components that exist).
class ShipCatalog {
 public:
  static ShipCatalog load(const std::filesystem::path& ships_dir);

  // Finds a vessel by name or alias, ignoring case, spaces and hyphens.
  // Unknown names throw InputError listing the known vessels.
  const VesselFile& vessel(std::string_view name) const;
  const TowlineFile& component(std::string_view name) const;
  // The same lookups without throwing: nullptr when unknown.
  const VesselFile* find_vessel(std::string_view name) const;
  const TowlineFile* find_component(std::string_view name) const;
  const std::vector<VesselFile>& vessels() const { return vessels_; }
  const std::vector<TowlineFile>& components() const { return components_; }

  // The towline a tug rigs: its wire or fiber hawser of the given length,
  // then its pendant (fixed length), ordered tug -> tow.
  model::Towline towline(const model::Vessel& tug, model::LineKind hawser, double hawser_length_m) const;

  const std::filesystem::path& directory() const { return directory_; }

  // A copy whose vessels and towline components named in the maps (canonical
  // name -> SHA-256) carry the given content_sha256 instead of their files':
  // the hashes that the keys of cases computed from an earlier version of a
  // file hold (sweep/build/rekey.hpp: re-keying cases when only comments changed).
  ShipCatalog with_content_hashes(const std::map<std::string, std::string>& vessel_sha256,
                                  const std::map<std::string, std::string>& component_sha256) const;

 private:
  std::filesystem::path directory_;
  std::vector<VesselFile> vessels_;
  std::vector<TowlineFile> components_;
  std::map<std::string, std::size_t> vessel_index_;     // normalized name/alias -> index
  std::map<std::string, std::size_t> component_index_;  // normalized name -> index
};

}  // namespace towdb::io

#endif  // TOWDB_IO_SHIP_FILE_HPP
