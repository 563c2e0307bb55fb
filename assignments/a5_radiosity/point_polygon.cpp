// A5.1 Point-to-polygon form factor (the contour integral).
#include "a5_tasks.h"
#include "render/student_task.h"

namespace ll::a5 {

float pointToPolygonFormFactor(Vec3 x, Vec3 n, const Vec3* vertices, int count) {
#if LIGHTLAB_SOLUTION  // A5.1
  double sum = 0.0;
  for (int k = 0; k < count; ++k) {
    const glm::dvec3 a = glm::dvec3(vertices[k] - x), b = glm::dvec3(vertices[(k + 1) % count] - x);
    const glm::dvec3 c = glm::cross(a, b);
    const double lc = glm::length(c);
    if (!(lc > 0.0)) continue;  // an edge pointing at x: no contribution
    const double beta = std::atan2(lc, glm::dot(a, b));  // the angle between a and b, stable near 0 and pi
    sum += beta * glm::dot(glm::dvec3(n), c) / lc;
  }
  return static_cast<float>(std::abs(sum) / (2.0 * static_cast<double>(kPi)));
#else
  // Your A5.1 here (see its comment in a5_tasks.h), then delete the line below.
  (void)x;
  (void)n;
  (void)vertices;
  (void)count;
  LIGHTLAB_TODO("A5.1", "point-to-polygon form factor (assignments/a5_radiosity/point_polygon.cpp)");
  return 0.0f;
#endif
}

}  // namespace ll::a5
