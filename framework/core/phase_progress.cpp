#include "core/phase_progress.h"

namespace ll {

namespace {
thread_local const PhaseSink* tSink = nullptr;
}

ScopedPhaseSink::ScopedPhaseSink(const PhaseSink* sink) : previous_(tSink) { tSink = sink; }
ScopedPhaseSink::~ScopedPhaseSink() { tSink = previous_; }

const PhaseSink* currentPhaseSink() { return tSink; }

void reportPhase(const std::string& phase, double fraction) {
  if (tSink && *tSink) (*tSink)(phase, fraction);
}

}  // namespace ll
