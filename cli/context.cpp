#include "cli.hpp"

namespace towdb::cli {

io::ShipCatalog load_catalog(const Context& ctx) {
  return io::ShipCatalog::load(ctx.ships_dir.empty() ? io::default_ships_dir()
                                                      : std::filesystem::path(ctx.ships_dir));
}

}  // namespace towdb::cli
