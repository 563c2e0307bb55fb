// RenderJob's phase reports: what a GUI pane's caption shows while a job runs.
#include "render/render_job.h"

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/phase_progress.h"
#include "modules/registry.h"
#include "scene/scene_loader.h"

namespace ll {
namespace {

const std::string kScenes = std::string(LIGHTLAB_DATA_DIR) + "/scenes/";

// A technique whose preparation reports a phase of its own (as radiosity's "patch mesh" and "form
// factors"), and whose passes report nothing.
class PreparingTechnique final : public Technique {
 public:
  void prepare(const RenderContext&) override { reportPhase("precomputing", 0.5); }
  void renderPass(const RenderContext&, int, FrameBuffer&, WorkCounters&, const std::atomic<bool>&) override {}
};

// A 4 x 4 job of PreparingTechnique over the Cornell box, brute force.
class RenderJobPhases : public ::testing::Test {
 protected:
  RenderJob job(int spp) {
    RenderSettings settings;
    settings.width = 4;
    settings.height = 4;
    settings.spp = spp;
    return RenderJob(scene_, *none_, technique_, params_, settings);
  }

 private:
  const Scene scene_ = loadScene(kScenes + "cornell_box.json");
  const std::unique_ptr<Accelerator> none_ =
      buildAccelerator(findAccelerator("none"), ParamSet("none", {}), scene_.geometry);
  PreparingTechnique technique_;
  const ParamSet params_{"technique 'test'", {}};
};

// The job says "pass" (at 0) once its preparation is over and before its first pass -- not before the
// preparation, where a pane would show "pass 1/N  0 %" while the technique still precomputes.
TEST_F(RenderJobPhases, ThePassPhaseComesAfterThePreparationAndBeforeThePasses) {
  RenderJob twoPasses = job(2);
  std::vector<std::pair<std::string, double>> phases;
  const PhaseSink sink = [&](const std::string& phase, double fraction) { phases.emplace_back(phase, fraction); };
  {
    const ScopedPhaseSink scoped(&sink);
    twoPasses.run([&](int done, int) { phases.emplace_back("(pass done)", static_cast<double>(done)); });
  }
  const std::vector<std::pair<std::string, double>> expected{
      {"precomputing", 0.5}, {"pass", 0.0}, {"(pass done)", 1.0}, {"(pass done)", 2.0}};
  EXPECT_EQ(phases, expected);
}

// Without a sink (the command line), the report goes nowhere and the job renders as before.
TEST_F(RenderJobPhases, AJobRunsWithoutAPhaseSink) {
  RenderJob onePass = job(1);
  onePass.run();
  EXPECT_EQ(onePass.stats().passes, 1);
}

}  // namespace
}  // namespace ll
