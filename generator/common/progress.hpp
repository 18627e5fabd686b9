// The one progress line of the command-line tools: a line on stderr redrawn
// in place ("\r" text), with a bar of '#' cells. `towdb build`
// (sweep/build/progress.hpp), `towdb simulate` and `towdb validate` format their own
// text around bar(); this class decides whether and when the line is drawn.
// It draws only when enabled and stderr is a terminal, so that logs and pipes
// stay clean.
#ifndef TOWDB_COMMON_PROGRESS_HPP
#define TOWDB_COMMON_PROGRESS_HPP

#include <chrono>
#include <string>

namespace towdb {

class ProgressLine {
 public:
  // Draws only if `enabled` and stderr is a TTY. A redraw that is not the
  // final one is due only once `min_redraw_s` has passed since the last.
  explicit ProgressLine(bool enabled, double min_redraw_s = 0.0);

  bool enabled() const { return enabled_; }
  // Seconds since construction.
  double elapsed_s() const;
  // Whether a redraw is due now (always when final); if so, counts it as done.
  bool due(bool final);
  // Writes "\r" + text, then ESC[K (clear the rest of the line) if
  // `clear_rest`, then a newline if `final`. Nothing when not enabled.
  void draw(const std::string& text, bool final, bool clear_rest = true) const;

  // `filled` '#' cells followed by width - filled `empty` cells.
  static std::string bar(int filled, int width, char empty);

 private:
  bool enabled_;
  double min_redraw_s_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace towdb

#endif  // TOWDB_COMMON_PROGRESS_HPP
