#include "gpu/offscreen_gl.h"

#include <string>

#include <GLFW/glfw3.h>

#include "core/error.h"

namespace ll::gpu {

namespace {
std::mutex gMutex;
GLFWwindow* gWindow = nullptr;  // hidden; only its context is used
}  // namespace

bool OffscreenGl::create(std::string* why) {
  if (gWindow) return true;
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  gWindow = glfwCreateWindow(16, 16, "LightLab GPU worker", nullptr, nullptr);
  glfwDefaultWindowHints();
  if (!gWindow && why) *why = "cannot create a hidden OpenGL 3.3 core context";
  return gWindow != nullptr;
}

void OffscreenGl::destroy() {
  std::lock_guard lock(gMutex);
  if (gWindow) glfwDestroyWindow(gWindow);
  gWindow = nullptr;
}

void OffscreenGl::createForCommandLine() {
  static std::string glfwError;
  glfwSetErrorCallback([](int code, const char* text) {
    glfwError = "GLFW error " + std::to_string(code) + ": " + text;
  });
  std::string why;
  if (!glfwInit() || !create(&why))
    throwUserError("this technique renders with OpenGL and needs a display (" +
                   (glfwError.empty() ? why : glfwError) +
                   "); under a headless server use xvfb-run");
}

bool OffscreenGl::available() {
  std::lock_guard lock(gMutex);
  return gWindow != nullptr;
}

OffscreenGl::Lease::Lease() : lock_(gMutex) {
  if (!gWindow)
    throwUserError(
        "this technique renders with OpenGL: it needs a display (lightlab gui, or the CLI with "
        "DISPLAY set)");
  glfwMakeContextCurrent(gWindow);
}

OffscreenGl::Lease::~Lease() {
  glfwMakeContextCurrent(nullptr);
}

}  // namespace ll::gpu
