// A5.2 One Gauss-Seidel sweep of B = E + rho F B.
#include "a5_tasks.h"
#include "render/student_task.h"

namespace ll::a5 {

float gaussSeidelSweep(const RadiositySystem& system, std::vector<Rgb>& b) {
  const FormFactors& f = system.f;
  float change = 0.0f;
#if LIGHTLAB_SOLUTION  // A5.2
  for (uint32_t i = 0; i < f.size(); ++i) {
    Rgb gathered(0.0f);
    for (uint32_t k = f.rowStart[i]; k < f.rowStart[i + 1]; ++k) gathered += f.value[k] * b[f.column[k]];
    const Patch& p = system.patches[i];
    const Rgb next = p.emission + p.reflectance * gathered;
    change = std::max(change, maxComponent(glm::abs(next - b[i])));
    b[i] = next;
  }
#else
  // Your A5.2 here (see its comment in a5_tasks.h), then delete the line below.
  (void)system;
  (void)b;
  (void)f;
  LIGHTLAB_TODO("A5.2", "Gauss-Seidel sweep (assignments/a5_radiosity/gauss_seidel.cpp)");
#endif
  return change;
}

}  // namespace ll::a5
