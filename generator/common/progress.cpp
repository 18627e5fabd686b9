#include "common/progress.hpp"

#include <cstdio>

#include <unistd.h>

namespace towdb {

ProgressLine::ProgressLine(bool enabled, double min_redraw_s)
    : enabled_(enabled && isatty(fileno(stderr)) != 0),
      min_redraw_s_(min_redraw_s),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_ - std::chrono::seconds(1)) {}

double ProgressLine::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool ProgressLine::due(bool final) {
  const auto now = std::chrono::steady_clock::now();
  if (!final && std::chrono::duration<double>(now - last_draw_).count() < min_redraw_s_) return false;
  last_draw_ = now;
  return true;
}

void ProgressLine::draw(const std::string& text, bool final, bool clear_rest) const {
  if (!enabled_) return;
  std::fprintf(stderr, "\r%s%s%s", text.c_str(), clear_rest ? "\x1b[K" : "", final ? "\n" : "");
  std::fflush(stderr);
}

std::string ProgressLine::bar(int filled, int width, char empty) {
  std::string cells(static_cast<std::size_t>(filled), '#');
  cells.append(static_cast<std::size_t>(width - filled), empty);
  return cells;
}

}  // namespace towdb
