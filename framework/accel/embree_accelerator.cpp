// Accelerator `embree`: Intel Embree 3 (Debian's libembree), the industrial
// yardstick the course's own accelerators are measured against. Triangles
// are Embree triangles (primitive ids [0, triangleCount)); spheres are a user
// geometry that calls the framework's own sphere test, so spheres hit
// exactly as brute force does. Embree's triangle test is not the framework's
// watertight one: t agrees to rounding, and a ray exactly through a shared
// edge may report the other triangle. Compiled only when Embree is found.
#include <xmmintrin.h>  // MXCSR: flush-to-zero / denormals-are-zero

#include <atomic>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>

#include "accel/accelerator.h"
#include "core/timer.h"

namespace ll {

namespace {

// Sets flush-to-zero and denormals-are-zero for the calling thread while in
// scope, as Embree asks of tracing threads (denormal arithmetic is very slow
// in its SIMD code), and restores the caller's mode after.
class DenormalsOff {
 public:
  DenormalsOff() : saved_(_mm_getcsr()) {
    const unsigned int wanted = saved_ | kFtz | kDaz;
    if (wanted != saved_) _mm_setcsr(wanted);
  }
  ~DenormalsOff() {
    if (_mm_getcsr() != saved_) _mm_setcsr(saved_);
  }
  DenormalsOff(const DenormalsOff&) = delete;
  DenormalsOff& operator=(const DenormalsOff&) = delete;

 private:
  static constexpr unsigned int kFtz = 0x8000u;  // _MM_FLUSH_ZERO_ON
  static constexpr unsigned int kDaz = 0x0040u;  // _MM_DENORMALS_ZERO_ON
  unsigned int saved_;
};

RTCRay toRtcRay(const Ray& ray) {
  RTCRay r;
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.tnear = ray.tmin;
  r.dir_x = ray.dir.x;
  r.dir_y = ray.dir.y;
  r.dir_z = ray.dir.z;
  r.time = 0.0f;
  r.tfar = ray.tmax;
  r.mask = 0xffffffffu;
  r.id = 0;
  r.flags = 0;
  return r;
}

class EmbreeAccelerator final : public Accelerator {
 public:
  EmbreeAccelerator(RTCBuildQuality quality, bool robust) : quality_(quality), robust_(robust) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw std::runtime_error("embree: cannot create a device");
    rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeAccelerator::monitorMemory, this);
  }
  ~EmbreeAccelerator() override {
    if (scene_) rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  EmbreeAccelerator(const EmbreeAccelerator&) = delete;
  EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

  void build(const Geometry& geometry) override {
    const Timer timer;
    geometry_ = &geometry;
    if (scene_) rtcReleaseScene(scene_);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, quality_);
    if (robust_) rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    if (geometry.triangleCount() > 0) addTriangles(geometry);
    if (!geometry.spheres.empty()) addSpheres(geometry);
    rtcCommitScene(scene_);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw std::runtime_error("embree: building the scene failed");
    buildSeconds_ = timer.seconds();
  }

  bool intersect(const Ray& ray, Hit& hit, QueryCounters&) const override {
    const DenormalsOff ftz;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray = toRtcRay(ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    hit = Hit{};
    hit.t = ray.tmax;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit.t = rh.ray.tfar;
    if (rh.hit.geomID == triangleGeomId_) {
      hit.prim = rh.hit.primID;
      hit.b1 = rh.hit.u;  // Embree's u, v weight vertices 1 and 2, as ours do
      hit.b2 = rh.hit.v;
    } else {
      hit.prim = geometry_->triangleCount() + rh.hit.primID;
    }
    return true;
  }

  bool occluded(const Ray& ray, QueryCounters&) const override {
    const DenormalsOff ftz;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r = toRtcRay(ray);
    rtcOccluded1(scene_, &context, &r);
    return r.tfar == -kInfinity;  // Embree marks an occluded ray with tfar = -inf
  }

  AcceleratorStats stats() const override {
    AcceleratorStats s;
    s.buildSeconds = buildSeconds_;
    const long long bytes = memory_.load();
    s.memoryBytes = bytes > 0 ? static_cast<size_t>(bytes) : 0;  // node count, depth, SAH: not exposed by Embree
    return s;
  }

 private:
  static bool monitorMemory(void* self, ssize_t bytes, bool) {
    static_cast<EmbreeAccelerator*>(self)->memory_ += bytes;
    return true;
  }

  void addTriangles(const Geometry& g) {
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), g.positions.size()));
    std::memcpy(vertices, g.positions.data(), g.positions.size() * sizeof(Vec3));
    auto* indices = static_cast<unsigned int*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned int), g.triangles.size()));
    std::memcpy(indices, g.triangles.data(), g.triangles.size() * sizeof(glm::uvec3));
    rtcCommitGeometry(geom);
    triangleGeomId_ = rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
  }

  void addSpheres(const Geometry& g) {
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, static_cast<unsigned int>(g.spheres.size()));
    rtcSetGeometryUserData(geom, const_cast<Geometry*>(&g));
    rtcSetGeometryBoundsFunction(geom, &sphereBounds, nullptr);
    rtcSetGeometryIntersectFunction(geom, &sphereIntersect);
    rtcSetGeometryOccludedFunction(geom, &sphereOccluded);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
  }

  static const Sphere& sphereOf(void* user, unsigned int primID) {
    return static_cast<const Geometry*>(user)->spheres[primID];
  }

  static void sphereBounds(const RTCBoundsFunctionArguments* args) {
    const Sphere& s = sphereOf(args->geometryUserPtr, args->primID);
    args->bounds_o->lower_x = s.center.x - s.radius;
    args->bounds_o->lower_y = s.center.y - s.radius;
    args->bounds_o->lower_z = s.center.z - s.radius;
    args->bounds_o->upper_x = s.center.x + s.radius;
    args->bounds_o->upper_y = s.center.y + s.radius;
    args->bounds_o->upper_z = s.center.z + s.radius;
  }

  static Ray fromRtcRay(const RTCRay& r) {
    Ray ray;
    ray.origin = Vec3(r.org_x, r.org_y, r.org_z);
    ray.dir = Vec3(r.dir_x, r.dir_y, r.dir_z);
    ray.tmin = r.tnear;
    ray.tmax = r.tfar;
    return ray;
  }

  // Single rays only (rtcIntersect1/rtcOccluded1: N == 1).
  static void sphereIntersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    const Ray ray = fromRtcRay(rh->ray);
    const Sphere& s = sphereOf(args->geometryUserPtr, args->primID);
    float t;
    if (!intersectSphere(ray, s.center, s.radius, ray.tmin, ray.tmax, t)) return;
    const Vec3 n = ray.at(t) - s.center;
    rh->ray.tfar = t;
    rh->hit.Ng_x = n.x;
    rh->hit.Ng_y = n.y;
    rh->hit.Ng_z = n.z;
    rh->hit.u = 0.0f;
    rh->hit.v = 0.0f;
    rh->hit.primID = args->primID;
    rh->hit.geomID = args->geomID;
    rh->hit.instID[0] = args->context->instID[0];
  }

  static void sphereOccluded(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    const Ray ray = fromRtcRay(*r);
    const Sphere& s = sphereOf(args->geometryUserPtr, args->primID);
    float t;
    if (intersectSphere(ray, s.center, s.radius, ray.tmin, ray.tmax, t)) r->tfar = -kInfinity;
  }

  RTCBuildQuality quality_;
  bool robust_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  const Geometry* geometry_ = nullptr;
  unsigned int triangleGeomId_ = RTC_INVALID_GEOMETRY_ID;
  std::atomic<long long> memory_{0};
  double buildSeconds_ = 0.0;
};

RTCBuildQuality buildQuality(const std::string& name) {
  if (name == "low") return RTC_BUILD_QUALITY_LOW;
  if (name == "high") return RTC_BUILD_QUALITY_HIGH;
  return RTC_BUILD_QUALITY_MEDIUM;
}

}  // namespace

AcceleratorInfo embreeAccelerator() {
  return {"embree",
          "Intel Embree 3 (rtcIntersect1 / rtcOccluded1): the industrial yardstick for the course's accelerators",
          {ParamDecl::choice("quality", "medium", {"low", "medium", "high"}, "Embree's BVH build quality"),
           ParamDecl::boolean("robust", true,
                              "Embree's robust mode: no cracks between triangles, a little slower (RTC_SCENE_FLAG_ROBUST)")},
          [](const ParamSet& p) -> std::unique_ptr<Accelerator> {
            return std::make_unique<EmbreeAccelerator>(buildQuality(p.getChoice("quality")), p.getBool("robust"));
          }};
}

}  // namespace ll
