// PNG plots through gnuplot (Debian package gnuplot-nox), written from data
// files in a temporary directory. A missing gnuplot is a clear error.
#ifndef TOWDB_CLI_PLOT_HPP
#define TOWDB_CLI_PLOT_HPP

#include <filesystem>
#include <string>
#include <vector>

namespace towdb::cli {

// Two panels: the daily maxima as a density histogram against the fitted
// Type I density (like thesis Figure 4-2), and the worst day's dynamic
// tension around its maximum. Tensions in kips, alpha in 1/kip.
void write_simulation_plot(const std::string& png_path, const std::vector<double>& maxima_kips, double gumbel_u_kips,
                           double gumbel_alpha_per_kip, const std::vector<double>& trace_kips, double dt_s, int day);

// Runs a gnuplot script; throws Error with gnuplot's message on failure.
void run_gnuplot(const std::string& script);

// A fresh, empty temporary directory for one plot's data files.
std::filesystem::path make_plot_data_dir(const std::string& prefix);

// run_gnuplot, then removes data_dir (the plot's data files) whether gnuplot
// succeeded or not.
void run_gnuplot_with_data(const std::string& script, const std::filesystem::path& data_dir);

}  // namespace towdb::cli

#endif  // TOWDB_CLI_PLOT_HPP
