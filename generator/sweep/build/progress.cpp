#include "sweep/build/progress.hpp"

#include <cmath>
#include <cstdio>

namespace towdb::sweep {

namespace {
// Redraw interval: often enough to look alive, rarely enough to cost nothing.
constexpr double kRedrawInterval_s = 0.2;
constexpr int kBarWidth = 24;

std::string duration_text(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  char buffer[48];
  if (s >= 86400) {
    std::snprintf(buffer, sizeof buffer, "%ldd%02ldh", s / 86400, (s % 86400) / 3600);
  } else if (s >= 3600) {
    std::snprintf(buffer, sizeof buffer, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  } else if (s >= 60) {
    std::snprintf(buffer, sizeof buffer, "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(buffer, sizeof buffer, "%lds", s);
  }
  return buffer;
}
}  // namespace

ProgressBar::ProgressBar(int total, bool enabled) : total_(total), line_(enabled, kRedrawInterval_s) {}

std::string ProgressBar::format(int done, int failed, int total, double elapsed_s) {
  const int finished = done + failed;
  const double fraction = total > 0 ? static_cast<double>(finished) / total : 1.0;
  const int filled = static_cast<int>(std::floor(fraction * kBarWidth));
  const std::string bar = ProgressLine::bar(filled, kBarWidth, '-');
  const double rate = elapsed_s > 0 ? finished / elapsed_s : 0.0;
  const std::string eta = finished == 0 ? "?" : duration_text((total - finished) / rate);
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "%d/%d cases [%s] %5.1f%%  %.2f cases/s  ETA %s  %d failed", finished, total,
                bar.c_str(), 100.0 * fraction, rate, eta.c_str(), failed);
  return buffer;
}

void ProgressBar::draw(int done, int failed, bool final) {
  if (!line_.enabled() || !line_.due(final)) return;
  line_.draw(format(done, failed, total_, line_.elapsed_s()), final);
}

void ProgressBar::update(int done, int failed) { draw(done, failed, false); }

void ProgressBar::finish(int done, int failed) { draw(done, failed, true); }

}  // namespace towdb::sweep
