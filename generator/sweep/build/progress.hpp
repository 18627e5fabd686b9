// The build's progress line on stderr: cases done/total, rate, ETA and
// failures, redrawn in place at most a few times a second (the line itself is
// common/progress.hpp). Only when stderr is a terminal; silent otherwise
// (logs and pipes stay clean).
#ifndef TOWDB_SWEEP_PROGRESS_HPP
#define TOWDB_SWEEP_PROGRESS_HPP

#include <string>

#include "common/progress.hpp"

namespace towdb::sweep {

class ProgressBar {
 public:
  // Draws only if `enabled` and stderr is a TTY.
  ProgressBar(int total, bool enabled);
  void update(int done, int failed);
  // Draws the final state and ends the line.
  void finish(int done, int failed);

  // The text of one progress line (no carriage return), for tests:
  // " 12/240 cases [##----------]  5.0%  0.50 cases/s  ETA 7m36s  1 failed".
  static std::string format(int done, int failed, int total, double elapsed_s);

 private:
  void draw(int done, int failed, bool final);
  int total_;
  ProgressLine line_;
};

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_PROGRESS_HPP
