// Accelerator `none`: tests every primitive. Always correct, always
// available, and the baseline every other accelerator is checked against.
#include "accel/accelerator.h"
#include "core/timer.h"

namespace ll {

namespace {

class BruteForce final : public Accelerator {
 public:
  void build(const Geometry& geometry) override { geometry_ = &geometry; }

  bool intersect(const Ray& ray, Hit& hit, QueryCounters& counters) const override {
    const WatertightRay wray(ray);
    hit = Hit{};
    hit.t = ray.tmax;
    const uint32_t n = geometry_->primitiveCount();
    for (uint32_t p = 0; p < n; ++p) geometry_->intersect(p, ray, wray, hit);
    counters.primitivesTested += n;
    return hit.valid();
  }

  bool occluded(const Ray& ray, QueryCounters& counters) const override {
    const WatertightRay wray(ray);
    Hit hit;
    hit.t = ray.tmax;
    const uint32_t n = geometry_->primitiveCount();
    for (uint32_t p = 0; p < n; ++p) {
      ++counters.primitivesTested;
      if (geometry_->intersect(p, ray, wray, hit)) return true;
    }
    return false;
  }

  AcceleratorStats stats() const override { return {}; }
  bool testsEveryPrimitive() const override { return true; }

 private:
  const Geometry* geometry_ = nullptr;
};

}  // namespace

AcceleratorInfo bruteForceAccelerator() {
  return {"none", "brute force: tests every primitive for every ray (the correctness baseline)", {},
          [](const ParamSet&) -> std::unique_ptr<Accelerator> { return std::make_unique<BruteForce>(); }};
}

}  // namespace ll
