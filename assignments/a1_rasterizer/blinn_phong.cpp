// A1.4 Blinn-Phong local shading, one light.
#include "a1_tasks.h"
#include "render/student_task.h"

namespace ll::a1 {

LightTerms blinnPhong(Vec3 n, Vec3 v, Vec3 l, Rgb irradiance, float shininess) {
#if LIGHTLAB_SOLUTION  // A1.4
  LightTerms out;
  const float nDotL = glm::dot(n, l);
  if (nDotL <= 0.0f) return out;
  const Vec3 h = glm::normalize(v + l);
  out.diffuse = irradiance * nDotL;
  out.specular = irradiance * std::pow(std::max(0.0f, glm::dot(n, h)), shininess);
  return out;
#else
  // Your A1.4 here (see its comment in a1_tasks.h), then delete the line below.
  (void)n;
  (void)v;
  (void)l;
  (void)irradiance;
  (void)shininess;
  LIGHTLAB_TODO("A1.4", "Blinn-Phong shading (assignments/a1_rasterizer/blinn_phong.cpp)");
  return {};
#endif
}

}  // namespace ll::a1
