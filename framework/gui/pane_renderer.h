// One GUI pane's renderer: a worker thread that runs a RenderJob pass by pass
// and publishes the resolved image after every pass. submit() replaces what
// is being rendered (camera, parameters, technique, scene) and returns at
// once: the running job is cancelled and the worker starts the newest
// request. The UI thread only ever copies a snapshot, so no UI frame waits
// on a render.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include "core/image.h"
#include "core/params.h"
#include "core/timer.h"
#include "render/light_path_mosaic.h"
#include "render/render_job.h"
#include "render/render_stats.h"
#include "scene/scene.h"

namespace ll::gui {

// What a pane shows: the technique's image, the accelerator's cost per pixel, or the image split into its
// light-path classes side by side (render/light_path_mosaic.h; techniques that split it: path).
enum class PaneView { Image, NodesVisited, PrimitivesTested, LightPaths };
inline bool isCostView(PaneView v) { return v == PaneView::NodesVisited || v == PaneView::PrimitivesTested; }
// What a pane's image is made by in view v: the technique, "<technique> light paths" or "<accelerator> cost".
std::string viewShows(PaneView v, const std::string& technique, const std::string& accelerator);

struct RenderRequest {
  std::shared_ptr<const Scene> scene;
  uint64_t sceneVersion =
      0;  // changes whenever the scene is (re)loaded: the accelerator is rebuilt
  std::string technique, accelerator;
  ParamSet techniqueParams, accelParams;
  RenderSettings settings;
  PaneView view = PaneView::Image;
  bool keepHistory = false;  // keep the image of passes, log-spaced in time (the cost-of-accuracy plot)
};

struct PaneSnapshot {
  enum class Phase { Idle, Building, Rendering, Done, Failed, Stopped };
  Phase phase = Phase::Idle;
  uint64_t version = 0;                // increases with every published image
  uint64_t request = 0;                // the submit() this snapshot reports on
  uint64_t imageRequest = 0;           // the submit() the image was rendered for
  uint64_t starts = 0;                 // renders the worker began: increases on every restart
  std::shared_ptr<const Image> image;  // linear radiance, stub pixels striped magenta
  // Only while `image` has stub stripes: the same radiance without them, as the reference (or, with a
  // task isolated, the stub) answered for those pixels. Errors and the plot measure measured().
  std::shared_ptr<const Image> unstriped;
  std::shared_ptr<const Image> measured() const { return unstriped ? unstriped : image; }
  bool preview = false;                // image is the quick low-resolution first look
  PaneView view = PaneView::Image;     // what `image` holds: radiance, per-pixel counts, or the light-path mosaic
  std::vector<MosaicTile> lightPathTiles;  // view LightPaths: where each class sits in `image` (empty: not split)
  std::string imageShows;               // what `image` was made by: the technique, or "<accelerator> cost"
  // `version` when the image was last cleared (a switch of technique or view):
  // display bytes of an older version belong to what the pane showed before.
  uint64_t clearedAt = 0;
  int passes = 0, totalPasses = 0;
  // Wall time of the request up to its last completed pass: every phase
  // (accelerator build, preview, the technique's preparation, passes).
  double seconds = 0.0;
  std::chrono::steady_clock::time_point started;  // when the request began, for a live clock
  double elapsed() const;     // seconds since `started` while building or rendering, else `seconds`
  // The phase in progress ("accelerator build (bvh)", "form factors (hemicube, 812 patches)",
  // "pass"), its progress in [0, 1] (< 0: unknown) and when it began.
  std::string phaseName;
  double phaseFraction = -1.0;
  std::chrono::steady_clock::time_point phaseStarted;
  // `seconds` broken down: this request's accelerator build (0 when cached), the
  // low-resolution preview's passes, the technique's preparation (radiosity's solve, whichever of the
  // preview and the full-size job ran it) and the passes.
  double requestBuildSeconds = 0.0, previewSeconds = 0.0, prepareSeconds = 0.0, passSeconds = 0.0;
  double buildSeconds = 0.0;  // accelerator build of the current scene
  RenderStats stats;          // as of the last completed pass
  std::map<std::string, std::string> missingTasks;  // student task id -> what
  std::set<std::string> exactFallbacks;  // missing tasks whose reference gives the same picture
  std::map<std::string, std::string> taskViolations;  // task id -> the rule its code broke
  std::map<std::string, bool> tasksRan;  // student tasks the render called -> answered by the reference
  std::string error;                     // set when phase == Failed
  // With RenderRequest::keepHistory: (seconds, measured()) of this request's passes, each
  // at least 1.5x the time of the one before it, and the latest pass last.
  std::vector<std::pair<double, std::shared_ptr<const Image>>> history;
};

class PaneRenderer {
 public:
  PaneRenderer();
  ~PaneRenderer();  // cancels and joins the worker
  PaneRenderer(const PaneRenderer&) = delete;
  PaneRenderer& operator=(const PaneRenderer&) = delete;

  // Cancels the current render and queues `request`; returns immediately with
  // the request's id. From then on only this request's results are published.
  uint64_t submit(RenderRequest request);
  // Stops rendering; the last image stays.
  void stop();
  PaneSnapshot snapshot() const;
  // True once the latest request has finished (or failed) and nothing is queued.
  bool finished() const;
  // The accelerator of the current scene (null before the first build); immutable once published.
  std::shared_ptr<const Accelerator> accelerator() const;

 private:
  void workerLoop();
  void render(const RenderRequest& request, uint64_t id);
  void renderCost(const RenderRequest& request, uint64_t id, PaneSnapshot s, const Timer& requestTimer);
  void publish(const PaneSnapshot& s);
  // Sets the phase of request `id` (ignored once superseded); thread-safe.
  void setPhase(uint64_t id, const std::string& phase, double fraction);

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<RenderRequest> pending_;
  RenderJob* running_ = nullptr;              // guarded by mutex_, for cancel
  std::atomic<bool>* runningCost_ = nullptr;  // the cost image's cancel flag, likewise
  void cancelRunning();                       // call with mutex_ held
  bool quit_ = false;
  bool busy_ = false;
  uint64_t submitted_ = 0;  // id of the newest request (or stop)
  PaneSnapshot snapshot_;

  // Worker-only state: the accelerator cache and the last pass time.
  std::shared_ptr<const Accelerator> accel_;
  std::shared_ptr<const Accelerator> publishedAccel_;  // guarded by mutex_, for the UI
  std::string accelKey_;
  double buildSeconds_ = 0.0;
  double lastPassSeconds_ = -1.0;  // the first full pass of the last render; < 0 = unknown
  uint64_t starts_ = 0;            // renders begun, for PaneSnapshot::starts
  std::string costKey_;

  std::thread worker_;  // last member: starts after everything above exists
};

}  // namespace ll::gui
