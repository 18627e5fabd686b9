// towdb: extreme towline tension database -- command-line entry point.
#include <cstdio>
#include <exception>
#include <iostream>

#include "cli.hpp"
#include "common/error.hpp"
#include "common/version.hpp"
#include "sweep/build/numerics.hpp"

int main(int argc, char** argv) {
  using towdb::cli::Context;
  CLI::App app{"towdb: extreme towline tension for open-ocean towing (tug, tow, sea, towline)", "towdb"};
  app.set_version_flag("--version", [] {
    return std::string("towdb ") + towdb::kVersion + " (numerics fingerprint " + towdb::sweep::numerics_fingerprint() +
           ")";
  });
  app.require_subcommand(1);
  Context ctx;
  app.add_option("--ships-dir", ctx.ships_dir,
                 "Directory of vessel files (default: $TOWDB_SHIPS_DIR or the bundled ships/)");
  towdb::cli::add_ships_command(app, ctx);
  towdb::cli::add_build_command(app, ctx);
  towdb::cli::register_case_runner();
  towdb::cli::add_mean_tension_command(app, ctx);
  towdb::cli::add_simulate_command(app, ctx);
  towdb::cli::add_query_commands(app, ctx);
  towdb::cli::add_export_command(app, ctx);
  towdb::cli::add_towline_command(app, ctx);
  towdb::cli::add_vessel_command(app, ctx);
  towdb::cli::add_validate_command(app, ctx);
  towdb::cli::add_audit_command(app, ctx);
  towdb::cli::add_plan_command(app, ctx);
  towdb::cli::add_refine_command(app, ctx);
  towdb::cli::add_serve_command(app, ctx);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // An unknown command word: name it and list the commands (CLI11 would only
    // say that a subcommand is required).
    const auto remaining = app.remaining();
    if (app.get_subcommands().empty() && !remaining.empty() && !remaining.front().empty() &&
        remaining.front().front() != '-') {
      std::string names;
      for (const CLI::App* sub : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + sub->get_name();
      std::cerr << "towdb: error: unknown command '" << remaining.front() << "'; the commands are: " << names
                << "\nRun 'towdb --help' for usage.\n";
      return 2;
    }
    std::cerr << "towdb: error: " << e.what() << "\nRun 'towdb --help' for usage.\n";
    return 2;
  } catch (const towdb::InputError& e) {
    std::cerr << "towdb: error: " << e.what() << "\n";
    return 2;
  }
  if (!ctx.action) {
    std::cerr << "towdb: error: no command given\nRun 'towdb --help' for usage.\n";
    return 2;
  }
  try {
    return ctx.action();
  } catch (const towdb::InputError& e) {
    std::cerr << "towdb: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "towdb: error: " << e.what() << "\n";
    return 1;
  }
}
