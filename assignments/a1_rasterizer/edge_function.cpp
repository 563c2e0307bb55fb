// A1.2 Edge functions and the top-left fill rule.
#include "a1_tasks.h"
#include "render/student_task.h"

namespace ll::a1 {

double edgeFunction(Vec2 a, Vec2 b, Vec2 p) {
#if LIGHTLAB_SOLUTION  // A1.2
  const double ax = a.x, ay = a.y;  // float -> double is exact, and so is every step below
  const double bx = static_cast<double>(b.x) - ax, by = static_cast<double>(b.y) - ay;
  const double px = static_cast<double>(p.x) - ax, py = static_cast<double>(p.y) - ay;
  return bx * py - by * px;
#else
  // Your A1.2 here (see its comment in a1_tasks.h), then delete the line below.
  (void)a;
  (void)b;
  (void)p;
  LIGHTLAB_TODO("A1.2", "edge functions and the top-left fill rule (assignments/a1_rasterizer/edge_function.cpp)");
  return 0.0;
#endif
}

bool isTopLeft(Vec2 a, Vec2 b) {
#if LIGHTLAB_SOLUTION  // A1.2
  const Vec2 d = b - a;
  // With y down and positive area, top edges run to the right, left edges run upwards.
  return (d.y == 0.0f && d.x > 0.0f) || d.y < 0.0f;
#else
  // Your A1.2 here (see its comment in a1_tasks.h), then delete the line below.
  (void)a;
  (void)b;
  LIGHTLAB_TODO("A1.2", "edge functions and the top-left fill rule (assignments/a1_rasterizer/edge_function.cpp)");
  return false;
#endif
}

}  // namespace ll::a1
