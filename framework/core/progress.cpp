#include "core/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ll {

namespace {
std::string formatDuration(double s) {
  char buf[32];
  if (s < 60.0)
    std::snprintf(buf, sizeof buf, "%.1fs", s);
  else
    std::snprintf(buf, sizeof buf, "%dm%02ds", static_cast<int>(s / 60.0), static_cast<int>(std::fmod(s, 60.0)));
  return buf;
}
}  // namespace

ProgressBar::ProgressBar(std::string label, double total, bool quiet)
    : label_(std::move(label)),
      total_(std::max(total, 1e-9)),
      active_(!quiet && isatty(STDERR_FILENO)),
      sink_(currentPhaseSink()) {
  if (sink_) (*sink_)(label_, 0.0);
}

ProgressBar::~ProgressBar() {
  if (active_ && !finished_) std::fputc('\n', stderr);
}

void ProgressBar::update(double done) {
  if (!active_ && !sink_) return;
  std::lock_guard lock(mutex_);
  const double now = timer_.seconds();
  if (sink_ && !finished_ && (now - lastReport_ >= 0.05 || done >= total_)) {
    lastReport_ = now;
    (*sink_)(label_, std::clamp(done / total_, 0.0, 1.0));
  }
  if (!active_) return;
  if (finished_ || (now - lastDraw_ < 0.1 && done < total_)) return;
  lastDraw_ = now;
  draw(done);
}

void ProgressBar::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  if (sink_) (*sink_)(label_, 1.0);
  if (!active_) {
    finished_ = true;
    return;
  }
  draw(total_);
  std::fputc('\n', stderr);
  finished_ = true;
}

void ProgressBar::draw(double done) {
  constexpr int kWidth = 30;
  const double fraction = std::clamp(done / total_, 0.0, 1.0);
  const int filled = static_cast<int>(fraction * kWidth);
  std::string bar(static_cast<size_t>(filled), '#');
  bar.resize(kWidth, '.');
  const double elapsed = timer_.seconds();
  const std::string eta = fraction > 0.0 && fraction < 1.0
                              ? " eta " + formatDuration(elapsed * (1.0 - fraction) / fraction)
                              : "";
  std::fprintf(stderr, "\r%s [%s] %3d%% %s%s   ", label_.c_str(), bar.c_str(),
               static_cast<int>(fraction * 100.0), formatDuration(elapsed).c_str(), eta.c_str());
  std::fflush(stderr);
}

}  // namespace ll
