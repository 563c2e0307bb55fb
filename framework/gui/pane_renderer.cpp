#include "gui/pane_renderer.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/phase_progress.h"
#include "core/timer.h"
#include "modules/registry.h"
#include "render/cost_image.h"
#include "tasks/task_modules.h"

namespace ll::gui {

std::string viewShows(PaneView v, const std::string& technique, const std::string& accelerator) {
  if (isCostView(v)) return accelerator + " cost";
  return v == PaneView::LightPaths ? technique + " light paths" : technique;
}

namespace {
// Thrown from a superseded request's progress report; caught (and dropped) by the worker loop.
struct Superseded : std::exception {
  const char* what() const noexcept override { return "superseded by a newer request"; }
};

// A first pass expected to be slower than this gets a quick low-resolution
// preview first, sized to take about kPreviewTarget, so opening a heavy scene
// or dragging the camera shows something at once. A pass of unknown cost (a
// new scene, technique or parameter) counts as slow.
constexpr double kPreviewAbove = 0.15;   // seconds
constexpr double kPreviewTarget = 0.05;  // seconds
constexpr int kMaxPreviewDivisor = 16;

// Resolution divisor for the preview of a pass expected to take `passSeconds` (< 0 = unknown).
int previewDivisor(double passSeconds) {
  if (passSeconds < 0.0) return 8;
  const int d = static_cast<int>(std::ceil(std::sqrt(passSeconds / kPreviewTarget)));
  return std::clamp(d, 2, kMaxPreviewDivisor);
}
}  // namespace

double PaneSnapshot::elapsed() const {
  if (phase != Phase::Rendering && phase != Phase::Building) return seconds;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

PaneRenderer::PaneRenderer() : worker_([this] { workerLoop(); }) {}

PaneRenderer::~PaneRenderer() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    pending_.reset();
    cancelRunning();
  }
  wake_.notify_all();
  worker_.join();
}

uint64_t PaneRenderer::submit(RenderRequest request) {
  uint64_t id = 0;
  {
    std::lock_guard lock(mutex_);
    pending_ = std::move(request);
    id = ++submitted_;
    cancelRunning();
  }
  wake_.notify_all();
  return id;
}

void PaneRenderer::stop() {
  std::lock_guard lock(mutex_);
  pending_.reset();
  ++submitted_;  // whatever is running now is superseded
  cancelRunning();
}

PaneSnapshot PaneRenderer::snapshot() const {
  std::lock_guard lock(mutex_);
  return snapshot_;
}

void PaneRenderer::cancelRunning() {
  if (running_) running_->cancel();
  if (runningCost_) *runningCost_ = true;
}

std::shared_ptr<const Accelerator> PaneRenderer::accelerator() const {
  std::lock_guard lock(mutex_);
  return publishedAccel_;
}

bool PaneRenderer::finished() const {
  std::lock_guard lock(mutex_);
  return !busy_ && !pending_;
}

void PaneRenderer::publish(const PaneSnapshot& s) {
  std::lock_guard lock(mutex_);
  if (s.request != submitted_) return;  // superseded: never show a stale view after a newer submit
  const uint64_t version = snapshot_.version + (s.image != snapshot_.image ? 1 : 0);
  // The phase is set by setPhase (from any thread); a publish of the same request keeps it.
  const bool sameRequest = snapshot_.request == s.request;
  std::string phaseName = std::move(snapshot_.phaseName);
  const double fraction = snapshot_.phaseFraction;
  const auto phaseStarted = snapshot_.phaseStarted;
  const uint64_t clearedAt = snapshot_.clearedAt;
  snapshot_ = s;
  snapshot_.version = version;
  snapshot_.clearedAt = s.image ? clearedAt : version;
  if (sameRequest) {
    snapshot_.phaseName = std::move(phaseName);
    snapshot_.phaseFraction = fraction;
    snapshot_.phaseStarted = phaseStarted;
  }
}

void PaneRenderer::setPhase(uint64_t id, const std::string& phase, double fraction) {
  std::lock_guard lock(mutex_);
  // A newer request, stop() or closing: the work reporting here (a radiosity solve, a
  // pass) is of no use any more. Unwinding from its progress report ends it at once.
  if (quit_ || id != submitted_) throw Superseded();
  if (snapshot_.request != id) return;
  if (snapshot_.phaseName != phase || fraction == 0.0) {  // a new phase, or the next pass
    snapshot_.phaseName = phase;
    snapshot_.phaseStarted = std::chrono::steady_clock::now();
  }
  snapshot_.phaseFraction = fraction;
}

void PaneRenderer::workerLoop() {
  for (;;) {
    RenderRequest request;
    uint64_t id = 0;
    {
      std::unique_lock lock(mutex_);
      busy_ = false;
      wake_.wait(lock, [this] { return quit_ || pending_.has_value(); });
      if (quit_) return;
      request = std::move(*pending_);
      pending_.reset();
      id = submitted_;
      busy_ = true;
    }
    try {
      render(request, id);
    } catch (const std::exception&
                 e) {  // UserError from a technique, or anything else: shown, never fatal
      PaneSnapshot s = snapshot();
      s.request = id;
      s.starts = starts_;
      s.phase = PaneSnapshot::Phase::Failed;
      s.error = e.what();
      publish(s);
    }
    std::lock_guard lock(mutex_);
    const auto phase = snapshot_.phase;
    if (!pending_ &&
        (phase == PaneSnapshot::Phase::Building || phase == PaneSnapshot::Phase::Rendering))
      snapshot_.phase = PaneSnapshot::Phase::Stopped;  // cancelled by stop(): the last image stays
  }
}

void PaneRenderer::render(const RenderRequest& request, uint64_t id) {
  PaneSnapshot s = snapshot();
  s.request = id;
  s.starts = ++starts_;
  s.error.clear();
  s.missingTasks.clear();
  s.taskViolations.clear();
  s.tasksRan.clear();
  s.passes = 0;
  s.seconds = 0.0;
  s.requestBuildSeconds = s.previewSeconds = s.prepareSeconds = s.passSeconds = 0.0;
  s.phaseName.clear();
  s.phaseFraction = -1.0;
  s.history.clear();
  s.started = std::chrono::steady_clock::now();
  const Timer requestTimer;  // every phase counts in the pane's time
  // A switch of technique or view: never the old picture under the new name.
  const std::string shows = viewShows(request.view, request.technique, request.accelerator);
  if (s.image && s.imageShows != shows) {
    s.image.reset();
    s.unstriped.reset();
  }
  if (s.phase != PaneSnapshot::Phase::Building) s.phase = PaneSnapshot::Phase::Rendering;
  publish(s);
  // What the technique and the tiles report (ProgressBar, reportPhase) goes to this pane.
  // A preview's passes are shown as the preview's progress, not as the first of the real passes.
  std::atomic<bool> inPreview{false};
  const PhaseSink sink = [this, id, &inPreview](const std::string& phase, double fraction) {
    setPhase(id, inPreview && phase == "pass" ? "preview" : phase, fraction);
  };
  const ScopedPhaseSink scopedSink(&sink);

  // The accelerator: rebuilt only when the scene or its own settings change.
  const AcceleratorInfo& accelInfo = findAccelerator(request.accelerator);
  // A hot reload (tasks::studentModuleGeneration) may have replaced the student's build code.
  const std::string key = std::to_string(request.sceneVersion) + "|" +
                          std::to_string(tasks::studentModuleGeneration()) + "|" + accelInfo.name + "|" +
                          request.accelParams.toJson().dump();
  if (key != accelKey_ || !accel_) {
    s.phase = PaneSnapshot::Phase::Building;
    publish(s);
    setPhase(id, "accelerator build (" + accelInfo.name + ")", -1.0);
    accel_.reset();
    accelKey_.clear();
    accel_ =
        buildAccelerator(accelInfo, request.accelParams, request.scene->geometry, &buildSeconds_);
    accelKey_ = key;
    s.requestBuildSeconds = buildSeconds_;
    std::lock_guard lock(mutex_);
    publishedAccel_ = accel_;
  }
  s.buildSeconds = buildSeconds_;
  if (isCostView(request.view)) return renderCost(request, id, s, requestTimer);
  const TechniqueInfo& techInfo = findTechnique(request.technique);
  // The cost of a pass is remembered per (scene, accelerator, technique, parameters, size).
  const std::string costKey =
      key + "|" + techInfo.name + "|" + request.techniqueParams.toJson().dump() + "|" +
      std::to_string(request.settings.width) + "x" + std::to_string(request.settings.height);
  if (costKey != costKey_) {
    costKey_ = costKey;
    lastPassSeconds_ = -1.0;
  }

  // The preview's preparation (radiosity's solve, which the full-size job then finds cached): shown
  // as preparation, not as the preview.
  double previewPrepareSeconds = 0.0;
  // Runs one job, publishing after each pass; false if cancelled.
  const auto runJob = [&](const RenderSettings& settings, bool preview) {
    const auto technique = techInfo.make();
    RenderSettings jobSettings = settings;
    jobSettings.lightPaths = request.view == PaneView::LightPaths;
    RenderJob job(*request.scene, *accel_, *technique, request.techniqueParams, jobSettings);
    {
      std::lock_guard lock(mutex_);
      if (pending_ || quit_) return false;
      running_ = &job;
    }
    // running_ must not outlive the job, however run() ends (a technique's error, Superseded).
    struct Unregister {
      PaneRenderer* self;
      ~Unregister() {
        std::lock_guard lock(self->mutex_);
        self->running_ = nullptr;
      }
    } unregister{this};
    s.phase = PaneSnapshot::Phase::Rendering;
    if (!preview) {
      s.passes = 0;
      s.totalPasses = settings.spp;  // the usual pass count, until the job says otherwise
    }
    publish(s);
    inPreview = preview;
    // Until the technique reports its own phases (radiosity's form factors) and the job its first pass.
    setPhase(id, preview ? "preview" : "preparing " + techInfo.name, -1.0);
    const Timer timer;
    // A render that fails (a crash in student code) keeps which tasks it ran, for the side panel and the
    // banner: the task that crashed was run by this pane, not "not run by these panes".
    const auto noteTasks = [&] {
      s.missingTasks = job.taskLog().missing();
      s.exactFallbacks = job.taskLog().exact();
      s.taskViolations = job.taskLog().violations();
      s.tasksRan = job.taskLog().ran();
    };
    struct KeepTasksOnFailure {
      PaneRenderer* self;
      PaneSnapshot& s;
      const decltype(noteTasks)& note;
      ~KeepTasksOnFailure() {
        if (std::uncaught_exceptions() == 0) return;
        note();
        self->publish(s);
      }
    } keepTasks{this, s, noteTasks};
    job.run([&](int done, int total) {
      s.lightPathTiles.clear();
      if (request.view == PaneView::LightPaths && job.frame().keepsLightPaths()) {
        LightPathMosaic mosaic = lightPathMosaic(job.frame());
        s.image = std::make_shared<const Image>(std::move(mosaic.image));
        s.unstriped.reset();
        s.lightPathTiles = std::move(mosaic.tiles);
      } else {
        s.image = std::make_shared<const Image>(job.frame().resolve());
        s.unstriped = job.frame().anyStub() ? std::make_shared<const Image>(job.frame().resolve(false)) : nullptr;
      }
      s.imageShows = shows;
      s.imageRequest = id;
      s.preview = preview;
      s.view = request.view;
      s.passes = preview ? 0 : done;
      s.totalPasses = preview ? 0 : total;
      s.seconds = requestTimer.seconds();
      s.stats = job.stats();
      if (preview) {
        previewPrepareSeconds = job.stats().prepareSeconds;
        s.prepareSeconds = previewPrepareSeconds;
        s.previewSeconds = timer.seconds() - previewPrepareSeconds;
      } else {
        if (request.keepHistory) {  // log-spaced: the point before the latest stays if 1.5x older
          auto& h = s.history;
          if (h.size() >= 2 && s.seconds < 1.5 * h[h.size() - 2].first)
            h.back() = {s.seconds, s.measured()};
          else
            h.emplace_back(s.seconds, s.measured());
        }
        s.prepareSeconds = previewPrepareSeconds + job.stats().prepareSeconds;
        s.passSeconds = job.stats().renderSeconds;
      }
      noteTasks();
      if (!preview && done == 1) lastPassSeconds_ = job.stats().renderSeconds;
      publish(s);
      setPhase(id, preview ? "preview" : "pass", preview ? -1.0 : 0.0);
    });
    return !job.cancelled();
  };

  const int divisor = previewDivisor(lastPassSeconds_);
  if ((lastPassSeconds_ < 0.0 || lastPassSeconds_ > kPreviewAbove) &&
      request.settings.width >= 8 * divisor && request.settings.height >= 8 * divisor) {
    RenderSettings preview = request.settings;
    preview.width = std::max(1, preview.width / divisor);
    preview.height = std::max(1, preview.height / divisor);
    preview.spp = 1;
    if (!runJob(preview, true)) return;
  }
  if (!runJob(request.settings, false)) return;
  s.phase = PaneSnapshot::Phase::Done;
  publish(s);
}

void PaneRenderer::renderCost(const RenderRequest& request, uint64_t id, PaneSnapshot s, const Timer& requestTimer) {
  std::atomic<bool> cancel{false};
  s.phase = PaneSnapshot::Phase::Rendering;
  publish(s);
  setPhase(id, "cost image", -1.0);  // (may throw Superseded: before runningCost_ points here)
  {
    std::lock_guard lock(mutex_);
    if (pending_ || quit_) return;
    runningCost_ = &cancel;
  }
  const Timer timer;
  const Camera camera = renderCamera(*request.scene, request.settings);
  const CostMetric metric = request.view == PaneView::NodesVisited ? CostMetric::NodesVisited
                                                                   : CostMetric::PrimitivesTested;
  Image counts = accelCostImage(*accel_, camera, metric, &cancel);
  {
    std::lock_guard lock(mutex_);
    runningCost_ = nullptr;
  }
  if (counts.empty()) return;
  s.image = std::make_shared<const Image>(std::move(counts));
  s.unstriped.reset();
  s.imageShows = request.accelerator + " cost";
  s.imageRequest = id;
  s.preview = false;
  s.view = request.view;
  s.passes = s.totalPasses = 1;
  s.passSeconds = timer.seconds();
  s.seconds = requestTimer.seconds();
  s.stats = RenderStats{};
  s.stats.work.rays[static_cast<size_t>(RayKind::Camera)] =
      static_cast<uint64_t>(camera.width) * camera.height;
  s.phase = PaneSnapshot::Phase::Done;
  publish(s);
}

}  // namespace ll::gui
