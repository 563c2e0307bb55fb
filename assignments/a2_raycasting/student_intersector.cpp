#include "student_intersector.h"

#include "a2_tasks.h"

namespace ll::a2 {

namespace {

class StudentIntersector final : public Accelerator {
 public:
  void build(const Geometry& geometry) override { g_ = &geometry; }

  bool intersect(const Ray& ray, Hit& hit, QueryCounters& counters) const override {
    hit = Hit{};
    Ray r = ray;
    for (uint32_t p = 0; p < g_->primitiveCount(); ++p)
      if (test(p, r, hit)) r.tmax = hit.t;  // only closer hits from now on
    counters.primitivesTested += g_->primitiveCount();
    return hit.valid();
  }

  bool occluded(const Ray& ray, QueryCounters& counters) const override {
    Hit hit;
    for (uint32_t p = 0; p < g_->primitiveCount(); ++p) {
      ++counters.primitivesTested;
      if (test(p, ray, hit)) return true;
    }
    return false;
  }

  AcceleratorStats stats() const override { return {}; }

 private:
  bool test(uint32_t p, const Ray& ray, Hit& hit) const {
    float t = 0.0f, b1 = 0.0f, b2 = 0.0f;
    bool found;
    if (g_->isTriangle(p)) {
      const glm::uvec3& tri = g_->triangles[p];
      found = rayTriangle(ray, g_->positions[tri.x], g_->positions[tri.y], g_->positions[tri.z], t, b1, b2);
    } else {
      found = raySphere(ray, g_->spheres[p - g_->triangleCount()], t);
    }
    // Trust but verify the interval, so a sloppy test cannot return hits behind the origin.
    if (!found || !(t > ray.tmin && t < ray.tmax)) return false;
    hit.t = t;
    hit.prim = p;
    hit.b1 = b1;
    hit.b2 = b2;
    return true;
  }

  const Geometry* g_ = nullptr;
};

}  // namespace

std::unique_ptr<Accelerator> makeStudentIntersector() { return std::make_unique<StudentIntersector>(); }

}  // namespace ll::a2
