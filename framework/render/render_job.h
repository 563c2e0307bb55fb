// Runs a technique pass by pass on worker threads, accumulating into a frame
// buffer; can be cancelled from another thread mid-frame. The CLI runs one to
// completion; the GUI runs one per pane and restarts it on any change.
#pragma once

#include <atomic>
#include <functional>

#include "render/technique.h"

namespace ll {

class RenderJob {
 public:
  // All references must outlive the job.
  RenderJob(const Scene& scene, const Accelerator& accel, Technique& technique, const ParamSet& params,
            RenderSettings settings);

  // Prepares, then renders passes until all are done or cancel() is called.
  // onPass(done, total) is called after each completed pass, from this thread.
  void run(const std::function<void(int done, int total)>& onPass = {});
  // Safe from any thread; run() returns after the tile in progress.
  void cancel() { cancel_ = true; }
  bool cancelled() const { return cancel_.load(); }

  const FrameBuffer& frame() const { return frame_; }
  const RenderStats& stats() const { return stats_; }  // complete once run() returned
  RenderStats& stats() { return stats_; }
  // Student tasks found missing so far (thread-safe; complete once run() returned).
  const TaskLog& taskLog() const { return taskLog_; }

 private:
  const Scene& scene_;
  const Accelerator& accel_;
  Technique& technique_;
  const ParamSet& params_;
  RenderSettings settings_;
  FrameBuffer frame_;
  RenderStats stats_;
  TaskLog taskLog_;
  std::atomic<bool> cancel_{false};
};

}  // namespace ll
