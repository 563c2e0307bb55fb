// A2.4 Blinn-Phong local shading.
#include "a2_tasks.h"
#include "render/student_task.h"

namespace ll::a2 {

Rgb blinnPhong(const ShadingInput& s, const LightInput& light) {
#if LIGHTLAB_SOLUTION  // A2.4
  const float falloff = std::isinf(light.distance) ? 1.0f : 1.0f / (light.distance * light.distance);
  const Rgb irradiance = light.intensity * falloff;  // I / r^2
  const Vec3 h = glm::normalize(s.v + light.l);
  const float diffuse = std::max(0.0f, glm::dot(s.n, light.l));
  const float specular = std::pow(std::max(0.0f, glm::dot(s.n, h)), s.shininess);
  return s.kd * irradiance * diffuse + s.ks * irradiance * specular;
#else
  // Your A2.4 here (see its comment in a2_tasks.h), then delete the line below.
  (void)s;
  (void)light;
  LIGHTLAB_TODO("A2.4", "Blinn-Phong shading (assignments/a2_raycasting/blinn_phong.cpp)");
  return Rgb(0.0f);
#endif
}

}  // namespace ll::a2
