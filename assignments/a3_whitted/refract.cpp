// A3.2 Refraction direction (Snell's law) and total internal reflection.
#include "a3_tasks.h"
#include "render/student_task.h"

namespace ll::a3 {

bool refract(Vec3 d, Vec3 n, float eta, Vec3& t) {
#if LIGHTLAB_SOLUTION  // A3.2
  const float cosI = -glm::dot(d, n);
  const float sin2T = eta * eta * std::max(0.0f, 1.0f - cosI * cosI);
  if (sin2T > 1.0f) return false;  // total internal reflection
  const float cosT = std::sqrt(1.0f - sin2T);
  t = glm::normalize(eta * d + (eta * cosI - cosT) * n);
  return true;
#else
  // Your A3.2 here (see its comment in a3_tasks.h), then delete the line below.
  (void)d;
  (void)n;
  (void)eta;
  (void)t;
  LIGHTLAB_TODO("A3.2", "refraction and total internal reflection (assignments/a3_whitted/refract.cpp)");
  return false;
#endif
}

}  // namespace ll::a3
