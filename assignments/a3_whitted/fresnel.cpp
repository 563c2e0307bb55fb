// A3.3 Fresnel equations (dielectric, s and p polarisation).
#include "a3_tasks.h"
#include "render/student_task.h"
#include "whitted_tracer.h"

namespace ll::a3 {

FresnelTerms fresnelDielectric(float cosI, float n1, float n2) {
#if LIGHTLAB_SOLUTION  // A3.3
  if (n1 == n2) return {0.0f, 0.0f};  // no interface (nested media of one index): even at grazing incidence
  const float c = std::clamp(cosI, 0.0f, 1.0f);
  const float sin2T = (n1 / n2) * (n1 / n2) * (1.0f - c * c);
  if (sin2T >= 1.0f) return {1.0f, 1.0f};  // total internal reflection
  const float cosT = std::sqrt(1.0f - sin2T);
  const float rs = (n1 * c - n2 * cosT) / (n1 * c + n2 * cosT);
  const float rp = (n2 * c - n1 * cosT) / (n2 * c + n1 * cosT);
  return {rs * rs, rp * rp};
#else
  // Your A3.3 here (see its comment in a3_tasks.h), then delete the line below.
  (void)cosI;
  (void)n1;
  (void)n2;
  LIGHTLAB_TODO("A3.3", "Fresnel equations (assignments/a3_whitted/fresnel.cpp)");
  return {};
#endif
}

}  // namespace ll::a3
