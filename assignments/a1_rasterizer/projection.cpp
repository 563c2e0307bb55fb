// A1.1 Projection.
#include "a1_tasks.h"
#include "render/student_task.h"

namespace ll::a1 {

Mat4 viewProjection(const Camera& camera, float near, float far) {
#if LIGHTLAB_SOLUTION  // A1.1
  // View: rows are the camera frame u (right), v (up), -w (backwards); the eye goes to the origin.
  const Vec3 w = glm::normalize(camera.target - camera.eye);
  const Vec3 u = glm::normalize(glm::cross(w, camera.up));
  const Vec3 v = glm::cross(u, w);
  Mat4 view(1.0f);  // glm is column-major: view[column][row]
  for (int c = 0; c < 3; ++c) {
    view[c][0] = u[c];
    view[c][1] = v[c];
    view[c][2] = -w[c];
  }
  view[3] = Vec4(-glm::dot(u, camera.eye), -glm::dot(v, camera.eye), glm::dot(w, camera.eye), 1.0f);
  // Perspective: x, y scaled by the focal length, w_clip = -z_view, z mapped to [-1, 1].
  const float f = 1.0f / std::tan(radians(camera.fovYDeg) * 0.5f);
  Mat4 projection(0.0f);
  projection[0][0] = f / camera.aspect();
  projection[1][1] = f;
  projection[2][2] = -(far + near) / (far - near);
  projection[2][3] = -1.0f;
  projection[3][2] = -2.0f * far * near / (far - near);
  return projection * view;
#else
  // Your A1.1 here (see its comment in a1_tasks.h), then delete the line below.
  (void)camera;
  (void)near;
  (void)far;
  LIGHTLAB_TODO("A1.1", "projection (assignments/a1_rasterizer/projection.cpp)");
  return Mat4(1.0f);
#endif
}

}  // namespace ll::a1
