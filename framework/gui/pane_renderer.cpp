#include "gui/pane_renderer.h"

#include <algorithm>
#include <exception>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/timer.h"
#include "modules/registry.h"

namespace ll::gui {

namespace {
// A first pass slower than this gets a quick quarter-resolution preview first,
// so dragging the camera stays fluid on heavy techniques.
constexpr double kPreviewAbove = 0.15;  // seconds
constexpr int kPreviewDivisor = 4;
}  // namespace

PaneRenderer::PaneRenderer() : worker_([this] { workerLoop(); }) {}

PaneRenderer::~PaneRenderer() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    pending_.reset();
    if (running_) running_->cancel();
  }
  wake_.notify_all();
  worker_.join();
}

void PaneRenderer::submit(RenderRequest request) {
  {
    std::lock_guard lock(mutex_);
    pending_ = std::move(request);
    if (running_) running_->cancel();
  }
  wake_.notify_all();
}

void PaneRenderer::stop() {
  std::lock_guard lock(mutex_);
  pending_.reset();
  if (running_) running_->cancel();
}

PaneSnapshot PaneRenderer::snapshot() const {
  std::lock_guard lock(mutex_);
  return snapshot_;
}

bool PaneRenderer::finished() const {
  std::lock_guard lock(mutex_);
  return !busy_ && !pending_;
}

void PaneRenderer::publish(const PaneSnapshot& s) {
  std::lock_guard lock(mutex_);
  const uint64_t version = snapshot_.version + (s.image != snapshot_.image ? 1 : 0);
  snapshot_ = s;
  snapshot_.version = version;
}

void PaneRenderer::workerLoop() {
  for (;;) {
    RenderRequest request;
    {
      std::unique_lock lock(mutex_);
      busy_ = false;
      wake_.wait(lock, [this] { return quit_ || pending_.has_value(); });
      if (quit_) return;
      request = std::move(*pending_);
      pending_.reset();
      busy_ = true;
    }
    try {
      render(request);
    } catch (const std::exception& e) {  // UserError from a technique, or anything else: shown, never fatal
      PaneSnapshot s = snapshot();
      s.phase = PaneSnapshot::Phase::Failed;
      s.error = e.what();
      publish(s);
    }
    std::lock_guard lock(mutex_);
    const auto phase = snapshot_.phase;
    if (!pending_ && (phase == PaneSnapshot::Phase::Building || phase == PaneSnapshot::Phase::Rendering))
      snapshot_.phase = PaneSnapshot::Phase::Stopped;  // cancelled by stop(): the last image stays
  }
}

void PaneRenderer::render(const RenderRequest& request) {
  PaneSnapshot s = snapshot();
  s.error.clear();
  s.missingTasks.clear();
  s.passes = 0;
  s.seconds = 0.0;

  // The accelerator: rebuilt only when the scene or its own settings change.
  const AcceleratorInfo& accelInfo = findAccelerator(request.accelerator);
  const std::string key =
      std::to_string(request.sceneVersion) + "|" + accelInfo.name + "|" + request.accelParams.toJson().dump();
  if (key != accelKey_ || !accel_) {
    s.phase = PaneSnapshot::Phase::Building;
    publish(s);
    accel_.reset();
    accelKey_.clear();
    accel_ = buildAccelerator(accelInfo, request.accelParams, request.scene->geometry, &buildSeconds_);
    accelKey_ = key;
  }
  s.buildSeconds = buildSeconds_;
  const TechniqueInfo& techInfo = findTechnique(request.technique);

  // Runs one job, publishing after each pass; false if cancelled.
  const auto runJob = [&](const RenderSettings& settings, bool preview) {
    const auto technique = techInfo.make();
    RenderJob job(*request.scene, *accel_, *technique, request.techniqueParams, settings);
    {
      std::lock_guard lock(mutex_);
      if (pending_ || quit_) return false;
      running_ = &job;
    }
    s.phase = PaneSnapshot::Phase::Rendering;
    s.preview = preview;
    publish(s);
    const Timer timer;
    job.run([&](int done, int total) {
      s.image = std::make_shared<const Image>(job.frame().resolve());
      s.passes = preview ? 0 : done;
      s.totalPasses = preview ? 0 : total;
      s.seconds = timer.seconds();
      s.stats = job.stats();
      s.missingTasks = job.taskLog().missing();
      if (!preview && done == 1) lastPassSeconds_ = s.seconds;
      publish(s);
    });
    {
      std::lock_guard lock(mutex_);
      running_ = nullptr;
    }
    return !job.cancelled();
  };

  if (lastPassSeconds_ > kPreviewAbove && request.settings.width >= 4 * kPreviewDivisor) {
    RenderSettings preview = request.settings;
    preview.width = std::max(1, preview.width / kPreviewDivisor);
    preview.height = std::max(1, preview.height / kPreviewDivisor);
    preview.spp = 1;
    if (!runJob(preview, true)) return;
  }
  if (!runJob(request.settings, false)) return;
  s.phase = PaneSnapshot::Phase::Done;
  publish(s);
}

}  // namespace ll::gui
