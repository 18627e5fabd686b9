#include "plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

#include "common/error.hpp"

namespace towdb::cli {

void run_gnuplot(const std::string& script) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto script_path = dir / ("towdb-plot-" + std::to_string(std::random_device{}()) + ".gp");
  { std::ofstream(script_path) << script; }
  const std::string cmd = "gnuplot '" + script_path.string() + "' 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) throw Error("cannot run gnuplot (install the Debian package gnuplot-nox)");
  std::string output;
  char buf[512];
  while (std::fgets(buf, sizeof buf, pipe)) output += buf;
  const int status = pclose(pipe);
  std::filesystem::remove(script_path);
  if (status != 0) throw Error("gnuplot failed (is gnuplot-nox installed?): " + output);
}

std::filesystem::path make_plot_data_dir(const std::string& prefix) {
  const auto dir = std::filesystem::temp_directory_path() / (prefix + "-" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir);
  return dir;
}

void run_gnuplot_with_data(const std::string& script, const std::filesystem::path& data_dir) {
  try {
    run_gnuplot(script);
  } catch (...) {
    std::filesystem::remove_all(data_dir);
    throw;
  }
  std::filesystem::remove_all(data_dir);
}

void write_simulation_plot(const std::string& png_path, const std::vector<double>& maxima_kips, double u,
                           double alpha, const std::vector<double>& trace_kips, double dt_s, int day) {
  const auto dir = make_plot_data_dir("towdb-plot");
  // Histogram of the daily maxima as a density.
  const auto [lo_it, hi_it] = std::minmax_element(maxima_kips.begin(), maxima_kips.end());
  const double lo = *lo_it, hi = *hi_it;
  const int bins = std::max(10, static_cast<int>(std::sqrt(static_cast<double>(maxima_kips.size()))));
  const double width = (hi - lo) / bins > 0 ? (hi - lo) / bins : 1.0;
  std::vector<int> counts(static_cast<std::size_t>(bins), 0);
  for (double x : maxima_kips) {
    const int b = std::min(bins - 1, static_cast<int>((x - lo) / width));
    ++counts[static_cast<std::size_t>(b)];
  }
  {
    std::ofstream h(dir / "hist.dat");
    for (int b = 0; b < bins; ++b) {
      h << lo + (b + 0.5) * width << " "
        << counts[static_cast<std::size_t>(b)] / (width * static_cast<double>(maxima_kips.size())) << "\n";
    }
    std::ofstream p(dir / "pdf.dat");
    const double x0 = lo - 2.0 * width, x1 = hi + 2.0 * width;
    for (int i = 0; i <= 400; ++i) {
      const double x = x0 + (x1 - x0) * i / 400.0;
      const double z = alpha * (x - u);
      p << x << " " << alpha * std::exp(-z - std::exp(-z)) << "\n";
    }
  }
  // 30 minutes of the worst day around its maximum.
  {
    const auto peak = std::max_element(trace_kips.begin(), trace_kips.end()) - trace_kips.begin();
    const long half = static_cast<long>(900.0 / dt_s);
    const long n = static_cast<long>(trace_kips.size());
    const long a = std::max(0L, static_cast<long>(peak) - half), b = std::min(n, static_cast<long>(peak) + half);
    std::ofstream t(dir / "trace.dat");
    for (long i = a; i < b; ++i) t << (static_cast<double>(i) + 1.0) * dt_s / 60.0 << " " << trace_kips[static_cast<std::size_t>(i)] << "\n";
  }
  const std::string d = dir.string();
  std::string script =
      "set terminal pngcairo size 1400,560 font 'sans,11'\n"
      "set output '" + png_path + "'\n"
      "set multiplot layout 1,2\n"
      "set title 'Daily maximum dynamic tension: simulation vs Type I'\n"
      "set xlabel 'dynamic tension (kips)'\nset ylabel 'probability density (1/kip)'\nset grid\n"
      "set style fill solid 0.4\n"
      "plot '" + d + "/hist.dat' using 1:2 with boxes title 'simulated days (" +
      std::to_string(maxima_kips.size()) + ")', '" + d + "/pdf.dat' using 1:2 with lines lw 2 title 'Type I fit'\n"
      "set title 'Dynamic tension on day " + std::to_string(day) + " around its maximum'\n"
      "set xlabel 'time (min)'\nset ylabel 'dynamic tension (kips)'\n"
      "plot '" + d + "/trace.dat' using 1:2 with lines lw 1 title ''\n"
      "unset multiplot\n";
  run_gnuplot_with_data(script, dir);
}

}  // namespace towdb::cli
