// The towdb CLI: each command lives in its own cmd_*.cpp and registers itself
// through one add_*_command function. Parsing (CLI11) fills plain structs;
// commands run after parsing, so every error goes through main()'s one
// exception-to-exit-code mapping: 0 ok, 2 bad input (InputError, usage),
// 1 anything else. `towdb query` returns kExitCheckFailed when it answers and
// a Navy Towing Manual check fails (README, "Exit codes").
#ifndef TOWDB_CLI_CLI_HPP
#define TOWDB_CLI_CLI_HPP

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "io/ship_file.hpp"

namespace towdb::cli {

// Exit code of an answered question whose safety check fails (not 0: a script
// must see it; not 1 or 2: those are errors and bad input).
inline constexpr int kExitCheckFailed = 3;

struct Context {
  std::string ships_dir;          // --ships-dir; empty = default
  std::function<int()> action;    // set by the chosen command's callback
};

// The vessel catalog of --ships-dir (or the default directory).
io::ShipCatalog load_catalog(const Context& ctx);

// Strict number parse: the whole text must be a finite number.
bool parse_number(const std::string& text, double* out);

// Checked before any work, so that a bad path costs nothing and writes
// nothing; each throws InputError naming the flag:
//   an output file: not empty, not a directory, in an existing directory;
void check_output_file(const std::string& flag, const std::string& path);
//   an output directory: not empty, not an existing file, its parent exists.
void check_output_dir(const std::string& flag, const std::string& path);

// A CLI11 check for a whole number >= 0 (a uint64 flag would wrap "-1").
CLI::Validator unsigned_integer();

// The check of every floating-point flag: a finite number (CLI::Range lets
// "nan" through) in [lo, hi], or (lo, hi] etc. when open.
CLI::Validator number_in(double lo, double hi, bool lo_open = false, bool hi_open = false);

void add_ships_command(CLI::App& app, Context& ctx);
void add_build_command(CLI::App& app, Context& ctx);  // build, status, sweep
// Registers the simulation chain as the case runner of `towdb build`.
void register_case_runner();
void add_mean_tension_command(CLI::App& app, Context& ctx);
void add_simulate_command(CLI::App& app, Context& ctx);
void add_query_commands(CLI::App& app, Context& ctx);  // query, max-speed, min-length
void add_export_command(CLI::App& app, Context& ctx);
void add_towline_command(CLI::App& app, Context& ctx);
void add_vessel_command(CLI::App& app, Context& ctx);
void add_validate_command(CLI::App& app, Context& ctx);  // thesis Appendix C comparison
void add_audit_command(CLI::App& app, Context& ctx);     // database answers vs direct simulation
void add_plan_command(CLI::App& app, Context& ctx);      // pictures for a tow plan (gnuplot PNGs)
void add_serve_command(CLI::App& app, Context& ctx);     // the planner web page and JSON API
void add_refine_command(CLI::App& app, Context& ctx);    // error-estimate-driven grid nodes

}  // namespace towdb::cli

#endif  // TOWDB_CLI_CLI_HPP
