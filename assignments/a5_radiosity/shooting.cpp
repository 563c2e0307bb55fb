// A5.3 Progressive refinement: shoot the largest unshot power (Southwell).
#include "a5_tasks.h"
#include "render/student_task.h"

namespace ll::a5 {

int shootLargest(const RadiositySystem& system, std::vector<Rgb>& b, std::vector<Rgb>& unshot) {
#if LIGHTLAB_SOLUTION  // A5.3
  const FormFactors& f = system.f;
  int shooter = -1;
  float best = 0.0f;
  for (uint32_t i = 0; i < f.size(); ++i) {
    const float power = maxComponent(unshot[i]) * system.patches[i].area;
    if (power > best) {
      best = power;
      shooter = static_cast<int>(i);
    }
  }
  if (shooter < 0) return -1;
  const auto i = static_cast<uint32_t>(shooter);
  const Rgb shot = unshot[i];
  const float ai = system.patches[i].area;
  unshot[i] = Rgb(0.0f);
  for (uint32_t k = f.rowStart[i]; k < f.rowStart[i + 1]; ++k) {
    const uint32_t j = f.column[k];
    const Patch& pj = system.patches[j];
    const Rgb received = pj.reflectance * (f.value[k] * ai / pj.area) * shot;  // rho_j F_ji unshot_i
    b[j] += received;
    unshot[j] += received;
  }
  return shooter;
#else
  // Your A5.3 here (see its comment in a5_tasks.h), then delete the line below.
  (void)system;
  (void)b;
  (void)unshot;
  LIGHTLAB_TODO("A5.3", "progressive refinement (assignments/a5_radiosity/shooting.cpp)");
  return -1;
#endif
}

}  // namespace ll::a5
