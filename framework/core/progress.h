// A terminal progress bar with rate and time-to-go estimate, for renders,
// solves, studies and grading. Silent when stderr is not a terminal or when
// constructed quiet, so logs and CI output stay clean. Thread-safe update().
// Whatever the terminal shows, the phase sink installed on the constructing
// thread (core/phase_progress.h: the GUI pane's) hears the label and fraction.
#pragma once

#include <atomic>
#include <mutex>
#include <string>

#include "core/phase_progress.h"
#include "core/timer.h"

namespace ll {

class ProgressBar {
 public:
  // total: units of work (passes, tiles, iterations); label: what is done.
  ProgressBar(std::string label, double total, bool quiet = false);
  ~ProgressBar();

  // Sets completed work to `done` (absolute) and redraws at most ~10 times/s.
  void update(double done);
  // Draws 100 % and ends the line (idempotent).
  void finish();
  bool active() const { return active_; }

 private:
  void draw(double done);

  std::string label_;
  double total_;
  bool active_;
  const PhaseSink* sink_;  // the constructing thread's, or null
  double lastReport_ = -1.0;
  bool finished_ = false;
  Timer timer_;
  double lastDraw_ = -1.0;
  std::mutex mutex_;
};

}  // namespace ll
