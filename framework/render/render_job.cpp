#include "render/render_job.h"

#include "core/phase_progress.h"
#include "core/timer.h"
#include "tasks/task_modes.h"

namespace ll {

RenderJob::RenderJob(const Scene& scene, const Accelerator& accel, Technique& technique, const ParamSet& params,
                     RenderSettings settings)
    : scene_(scene), accel_(accel), technique_(technique), params_(params), settings_(settings),
      frame_(settings.width, settings.height) {}

void RenderJob::run(const std::function<void(int, int)>& onPass) {
  RenderContext ctx{scene_, accel_, params_, settings_, &taskLog_};
  stats_.width = settings_.width;
  stats_.height = settings_.height;
  stats_.spp = settings_.spp;
  stats_.accel = accel_.stats();
  {
    const ScopedTaskLog scoped(&taskLog_);
    const Timer prepare;
    technique_.prepare(ctx);
    stats_.prepareSeconds = prepare.seconds();
  }
  // (After prepare(): whether a technique can split may depend on its parameters, e.g. radiosity's solver.)
  if (settings_.lightPaths && technique_.splitsLightPaths()) frame_.enableLightPaths();
  const int total = technique_.passCount(ctx);
  reportPhase("pass", 0.0);  // the preparation is over (a GUI pane's caption; nothing without a sink)
  const Timer timer;
  for (int pass = 0; pass < total && !cancel_; ++pass) {
    const ScopedTaskLog scoped(&taskLog_);
    technique_.renderPass(ctx, pass, frame_, stats_.work, cancel_);
    if (cancel_) break;
    stats_.skipped = technique_.skippedWork();  // (decided in prepare(), or as late as the last pass)
    frame_.completePass();
    stats_.passes = frame_.passes();
    stats_.renderSeconds = timer.seconds();
    if (onPass) onPass(frame_.passes(), total);
  }
  stats_.renderSeconds = timer.seconds();
  stats_.cancelled = cancel_;
  stats_.missingTasks = taskLog_.missing();
  stats_.exactFallbacks = taskLog_.exact();
  stats_.taskViolations = taskLog_.violations();
  stats_.referenceTasks = tasks::referenceList();
  stats_.skipped = technique_.skippedWork();
  stats_.lightPaths = lightPathShares(frame_);
}

}  // namespace ll
