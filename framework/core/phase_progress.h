// Where long work says what it is doing: a named phase ("form factors",
// "pass") and how far it is (0..1). The GUI's pane worker installs a sink
// on its thread for the time of one render; ProgressBar (which every long
// solve already uses for the terminal) and the pixel techniques' tiles
// report through it, so a pane can show "form factors 37 %" instead of a
// stale picture. Nothing is reported when no sink is installed.
#pragma once

#include <functional>
#include <string>

namespace ll {

// phase: a short name shown to people; fraction in [0, 1], or < 0 when unknown.
// Called from any thread the work runs on (oneTBB workers included): must be thread-safe.
using PhaseSink = std::function<void(const std::string& phase, double fraction)>;

// Installs `sink` (may be null) as this thread's for the scope's lifetime.
class ScopedPhaseSink {
 public:
  explicit ScopedPhaseSink(const PhaseSink* sink);
  ~ScopedPhaseSink();
  ScopedPhaseSink(const ScopedPhaseSink&) = delete;
  ScopedPhaseSink& operator=(const ScopedPhaseSink&) = delete;

 private:
  const PhaseSink* previous_;
};

// This thread's sink (null if none). Work that fans out to other threads
// takes it here first and calls it from there.
const PhaseSink* currentPhaseSink();

// Reports to this thread's sink, if any.
void reportPhase(const std::string& phase, double fraction = -1.0);

}  // namespace ll
