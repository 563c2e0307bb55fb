// Accelerator benchmarks: closest-hit and any-hit throughput (Mrays/s, one
// thread unless the name says t2) for coherent (camera) and incoherent
// (random origin in the scene's box, random direction) rays, for the rays a
// path tracer really traces (recorded from `path` on the Cornell box with the
// bunny: camera and bounce rays closest-hit, shadow rays any-hit), and build time,
// for every BVH split method, the KD-tree, the octree and Embree in the same
// run, on the bunny (3.7k, 59k, 235k triangles), the Cornell box with the 59k
// and the 235k bunny, and a soup of 1M random triangles.
//
//   build-dir/tests/bench/lightlab_bench --benchmark_filter=Accel
//     --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
//     --benchmark_min_time=0.2 --benchmark_format=json > accel.json
//   python3 tests/bench/accel_ratios.py accel.json    # ratios to Embree, median of pairs
//
// Ratios near a target: the Accel/paired benchmarks time an accelerator and Embree
// taking turns on the same path rays (see tracePaired), e.g.
//   --benchmark_filter='Accel/paired/closest/cornell235k/path/bvh-sah' --benchmark_repetitions=5
//
// The scenes, ray sets and built accelerators are made once, outside the timing.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "modules/registry.h"
#include "render/render_job.h"
#include "scene/camera.h"
#include "scene/scene_loader.h"

namespace {

using namespace ll;

struct BenchScene {
  const char* name;
  std::string path;  // empty: the random soup
};

const std::vector<BenchScene>& benchScenes() {
  static const std::vector<BenchScene> kScenes = {
      {"bunny3.7k", std::string(LIGHTLAB_DATA_DIR) + "/scenes/bunny.json"},
      {"bunny59k", std::string(LIGHTLAB_BUILD_DATA_DIR) + "/scenes/bunny_59k.json"},
      {"bunny235k", std::string(LIGHTLAB_BUILD_DATA_DIR) + "/scenes/bunny_235k.json"},
      {"cornell59k", std::string(LIGHTLAB_BUILD_DATA_DIR) + "/scenes/cornell_bunny_59k.json"},
      {"cornell235k", std::string(LIGHTLAB_BUILD_DATA_DIR) + "/scenes/cornell_bunny_235k.json"},
      {"soup1M", ""},
  };
  return kScenes;
}

// One million random triangles (edges about 1/50) in the unit cube, seen
// from a camera in front of it.
Scene randomSoup() {
  Scene s;
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> u(0.0f, 1.0f), d(-0.02f, 0.02f);
  constexpr uint32_t kTriangles = 1000000;
  Geometry& g = s.geometry;
  g.positions.reserve(3 * kTriangles);
  for (uint32_t i = 0; i < kTriangles; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    for (int k = 0; k < 3; ++k) g.positions.push_back(c + Vec3(d(rng), d(rng), d(rng)));
    g.triangles.emplace_back(3 * i, 3 * i + 1, 3 * i + 2);
    g.triangleObject.push_back(0);
  }
  s.camera.eye = Vec3(0.5f, 0.5f, -1.5f);
  s.camera.target = Vec3(0.5f);
  s.camera.fovYDeg = 40.0f;
  return s;
}

struct BenchAccel {
  const char* label;
  const char* name;
  std::vector<std::string> sets;
};

const std::vector<BenchAccel>& benchAccels() {
  static const std::vector<BenchAccel> kAccels = [] {
    std::vector<BenchAccel> a = {{"bvh-sah", "bvh", {"split=sah"}},
                                 {"bvh-median", "bvh", {"split=median"}},
                                 {"bvh-equal", "bvh", {"split=equal-counts"}},
                                 {"bvh-sah-sphere", "bvh", {"split=sah", "volume=sphere"}},
                                 {"bvh4", "bvh4", {}},
                                 {"kdtree", "kdtree", {}},
                                 {"kdtree-binned", "kdtree", {"build=binned"}},
                                 {"bsp", "bsp", {}},
                                 {"bsp-axis", "bsp", {"triangle_planes=0"}},  // no auto-partition
                                 {"octree", "octree", {}}};
    for (const AcceleratorInfo& info : accelerators())
      if (info.name == "embree") {
        a.push_back({"embree", "embree", {"robust=false"}});  // Embree's own defaults: the yardstick
        a.push_back({"embree-robust", "embree", {"robust=true"}});
      }
    return a;
  }();
  return kAccels;
}

// The yardstick: Embree with its own defaults (null without Embree).
const BenchAccel* embreeDefaults() {
  for (const BenchAccel& a : benchAccels())
    if (std::string(a.label) == "embree") return &a;
  return nullptr;
}

const Scene& scene(const BenchScene& s) {
  static std::map<std::string, std::unique_ptr<Scene>> cache;
  auto& slot = cache[s.name];
  if (!slot) slot = std::make_unique<Scene>(s.path.empty() ? randomSoup() : loadScene(s.path));
  return *slot;
}

ParamSet paramsOf(const BenchAccel& a) {
  const AcceleratorInfo& info = findAccelerator(a.name);
  ParamSet p(std::string("accelerator '") + a.name + "'", info.params);
  for (const auto& v : a.sets) p.assign(v);
  return p;
}

const Accelerator& accelerator(const BenchScene& s, const BenchAccel& a) {
  static std::map<std::string, std::unique_ptr<Accelerator>> cache;
  auto& slot = cache[std::string(s.name) + "/" + a.label];
  if (!slot) slot = buildAccelerator(findAccelerator(a.name), paramsOf(a), scene(s).geometry);
  return *slot;
}

constexpr int kImageSize = 256;  // camera rays: one per pixel of a 256x256 image

const std::vector<Ray>& rays(const BenchScene& s, bool coherent) {
  static std::map<std::string, std::vector<Ray>> cache;
  auto& slot = cache[std::string(s.name) + (coherent ? "/coherent" : "/incoherent")];
  if (!slot.empty()) return slot;
  const Scene& sc = scene(s);
  if (coherent) {
    Camera cam = sc.camera;
    cam.width = cam.height = kImageSize;
    const CameraFrame frame(cam);
    for (int y = 0; y < kImageSize; ++y)
      for (int x = 0; x < kImageSize; ++x)
        slot.push_back(referenceCameraRay(cam, frame, float(x) + 0.5f, float(y) + 0.5f));
  } else {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::normal_distribution<float> n;
    const Bounds3 b = sc.geometry.sceneBounds();
    for (int i = 0; i < kImageSize * kImageSize; ++i) {
      Ray r;
      r.origin = b.min + Vec3(u(rng), u(rng), u(rng)) * b.extent();
      r.dir = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
      slot.push_back(r);
    }
  }
  return slot;
}

// The rays a path tracer really traces: every query of `path` (its defaults: MIS, Russian roulette) rendering
// the scene at 96x96 with 16 spp on one thread, in the order it makes them (tile by tile, pixel by pixel,
// each path's bounces in turn). Closest-hit queries are its camera and bounce rays, any-hit queries its
// shadow rays towards the lights.
class RecordingAccelerator final : public Accelerator {
 public:
  explicit RecordingAccelerator(const Accelerator& inner) : inner_(inner) {}
  void build(const Geometry&) override {}
  bool intersect(const Ray& ray, Hit& hit, QueryCounters& counters) const override {
    {
      const std::lock_guard lock(mutex_);
      closest.push_back(ray);
    }
    return inner_.intersect(ray, hit, counters);
  }
  bool occluded(const Ray& ray, QueryCounters& counters) const override {
    {
      const std::lock_guard lock(mutex_);
      shadow.push_back(ray);
    }
    return inner_.occluded(ray, counters);
  }
  AcceleratorStats stats() const override { return inner_.stats(); }
  mutable std::vector<Ray> closest, shadow;

 private:
  const Accelerator& inner_;
  mutable std::mutex mutex_;  // (the render runs on one thread, so the order is the path tracer's)
};

struct PathRays {
  std::vector<Ray> closest, shadow;
};

const PathRays& pathRays(const BenchScene& s) {
  static std::map<std::string, PathRays> cache;
  auto it = cache.find(s.name);
  if (it != cache.end()) return it->second;
  const Scene& sc = scene(s);
  const AcceleratorInfo& bvh = findAccelerator("bvh");
  const auto inner = buildAccelerator(bvh, ParamSet(bvh.name, bvh.params), sc.geometry);
  RecordingAccelerator recorder(*inner);
  const TechniqueInfo& path = findTechnique("path");
  const auto technique = path.make();
  RenderSettings rs;
  rs.width = rs.height = 96;
  rs.spp = 16;
  rs.seed = 1;
  const ParamSet params(path.name, path.params);  // (RenderJob keeps a reference)
  tbb::task_arena(1).execute([&] {
    RenderJob job(sc, recorder, *technique, params, rs);
    job.run();
  });
  return cache[s.name] = PathRays{std::move(recorder.closest), std::move(recorder.shadow)};
}

enum class RaySet { Coherent, Incoherent, Path };

const std::vector<Ray>& raySet(const BenchScene& s, RaySet set, bool anyHit) {
  if (set != RaySet::Path) return rays(s, set == RaySet::Coherent);
  return anyHit ? pathRays(s).shadow : pathRays(s).closest;
}

// Traces rays[begin, end) through `accel` (any hit or closest hit), adding to `counters`.
void traceRange(const Accelerator& accel, const std::vector<Ray>& rays, size_t begin, size_t end, bool anyHit,
                QueryCounters& counters) {
  uint64_t local = 0;
  for (size_t i = begin; i != end; ++i) {
    Hit h;
    local += anyHit ? accel.occluded(rays[i], counters) : accel.intersect(rays[i], h, counters);
  }
  benchmark::DoNotOptimize(local);
}

void trace(benchmark::State& state, const BenchScene& s, const BenchAccel& a, RaySet set, bool anyHit,
           int threads) {
  const Accelerator& accel = accelerator(s, a);
  const std::vector<Ray>& rs = raySet(s, set, anyHit);
  tbb::task_arena arena(threads);
  std::atomic<uint64_t> nodes{0}, prims{0};  // over all iterations, for the per-ray means
  for (auto _ : state) {
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, rs.size(), 1024), [&](const tbb::blocked_range<size_t>& range) {
        QueryCounters counters;
        traceRange(accel, rs, range.begin(), range.end(), anyHit, counters);
        nodes += counters.nodesVisited;
        prims += counters.primitivesTested;
      });
    });
  }
  state.counters["Mrays/s"] =
      benchmark::Counter(static_cast<double>(rs.size()) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  // Per ray (Embree reports no counters: 0).
  const double queries = static_cast<double>(rs.size()) * static_cast<double>(state.iterations());
  state.counters["nodes/ray"] = static_cast<double>(nodes.load()) / queries;
  state.counters["prims/ray"] = static_cast<double>(prims.load()) / queries;
}

// Accel/paired/...: `a` and the yardstick on the same path rays, one thread,
// taking turns every kPairChunk rays (who goes first alternates) and timed
// chunk by chunk. A noisy neighbour on a shared machine then slows both
// alike, where separate benchmarks seconds apart can put one run's ratio
// 10-20 % off. Counters: `ratio` = the yardstick's time over a's (a's
// throughput relative to the yardstick's), and both rates in Mrays/s.
constexpr size_t kPairChunk = 16384;  // rays per turn: a few milliseconds

void tracePaired(benchmark::State& state, const BenchScene& s, const BenchAccel& a, const BenchAccel& yardstick,
                 bool anyHit) {
  const Accelerator& mine = accelerator(s, a);
  const Accelerator& theirs = accelerator(s, yardstick);
  const std::vector<Ray>& rs = raySet(s, RaySet::Path, anyHit);
  const auto seconds = [&](const Accelerator& accel, size_t begin, size_t end) {
    const auto start = std::chrono::steady_clock::now();
    QueryCounters counters;
    traceRange(accel, rs, begin, end, anyHit, counters);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  double mineSeconds = 0.0, theirSeconds = 0.0;
  bool mineFirst = true;
  for (auto _ : state)
    for (size_t begin = 0; begin < rs.size(); begin += kPairChunk, mineFirst = !mineFirst) {
      const size_t end = std::min(begin + kPairChunk, rs.size());
      if (mineFirst) mineSeconds += seconds(mine, begin, end);
      theirSeconds += seconds(theirs, begin, end);
      if (!mineFirst) mineSeconds += seconds(mine, begin, end);
    }
  const double rays = static_cast<double>(rs.size()) * static_cast<double>(state.iterations());
  state.counters["ratio"] = theirSeconds / mineSeconds;
  state.counters["Mrays/s"] = rays * 1e-6 / mineSeconds;
  state.counters[std::string(yardstick.label) + " Mrays/s"] = rays * 1e-6 / theirSeconds;
}

void build(benchmark::State& state, const BenchScene& s, const BenchAccel& a) {
  const Geometry& g = scene(s).geometry;
  const AcceleratorInfo& info = findAccelerator(a.name);
  const ParamSet p = paramsOf(a);
  for (auto _ : state) {
    auto accel = buildAccelerator(info, p, g);
    benchmark::DoNotOptimize(accel.get());
  }
  state.counters["Mprims/s"] = benchmark::Counter(static_cast<double>(g.primitiveCount()) * 1e-6,
                                                  benchmark::Counter::kIsIterationInvariantRate);
}

// Registers Accel/<closest|anyhit>/<scene>/<coherent|incoherent|path>/<accel>[/t2],
// Accel/paired/<closest|anyhit>/<scene>/path/<accel> and Accel/build/<scene>/<accel>.
// `path` rays (closest: camera and bounce rays; anyhit: shadow rays) only on the
// scenes a path tracer lights: the Cornell box with the bunny.
const bool kRegistered = [] {
  for (const BenchScene& s : benchScenes())
    for (const BenchAccel& a : benchAccels()) {
      const bool lit = std::string(s.name).starts_with("cornell");
      for (bool anyHit : {false, true})
        for (RaySet set : {RaySet::Coherent, RaySet::Incoherent, RaySet::Path}) {
          if (set == RaySet::Path && !lit) continue;
          const char* setName = set == RaySet::Coherent ? "coherent/" : set == RaySet::Incoherent ? "incoherent/" : "path/";
          const std::string name =
              std::string("Accel/") + (anyHit ? "anyhit/" : "closest/") + s.name + "/" + setName + a.label;
          benchmark::RegisterBenchmark(name.c_str(), [&s, &a, set, anyHit](benchmark::State& st) {
            trace(st, s, a, set, anyHit, 1);
          })->Unit(benchmark::kMillisecond)->UseRealTime();
          if (!anyHit && ((set == RaySet::Incoherent && std::string(s.name) == "bunny59k") || set == RaySet::Path))
            benchmark::RegisterBenchmark((name + "/t2").c_str(), [&s, &a, set](benchmark::State& st) {
              trace(st, s, a, set, false, 2);
            })->Unit(benchmark::kMillisecond)->UseRealTime();
        }
      const BenchAccel* yardstick = embreeDefaults();
      if (lit && yardstick && yardstick != &a)
        for (bool anyHit : {false, true})
          benchmark::RegisterBenchmark(
              (std::string("Accel/paired/") + (anyHit ? "anyhit/" : "closest/") + s.name + "/path/" + a.label).c_str(),
              [&s, &a, yardstick, anyHit](benchmark::State& st) { tracePaired(st, s, a, *yardstick, anyHit); })
              ->Unit(benchmark::kMillisecond)
              ->UseRealTime();
      benchmark::RegisterBenchmark((std::string("Accel/build/") + s.name + "/" + a.label).c_str(),
                                   [&s, &a](benchmark::State& st) { build(st, s, a); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
  return true;
}();

}  // namespace
