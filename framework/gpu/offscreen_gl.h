// An OpenGL 3.3 core context for techniques that render on the GPU from a
// worker thread. GLFW creates windows only on the main thread, so the GUI
// (or the CLI, when a display exists) calls OffscreenGl::create() there at
// start-up; a technique then borrows the context with OffscreenGl::Lease,
// which makes it current on the calling thread until the lease ends. One
// lease at a time: GPU panes take turns.
#pragma once

#include <memory>
#include <mutex>
#include <string>

struct GLFWwindow;

namespace ll::gpu {

class OffscreenGl {
 public:
  // Main thread, after glfwInit(). Returns false (with the reason in *why)
  // if no OpenGL 3.3 core context can be created.
  static bool create(std::string* why = nullptr);
  // Main thread, before glfwTerminate().
  static void destroy();
  // For the command line: initialises GLFW and creates the context, or throws
  // UserError naming why (no display). Safe to call twice.
  static void createForCommandLine();
  static bool available();

  class Lease {
   public:
    Lease();   // blocks until the context is free; throws UserError if there is none
    ~Lease();  // releases the context from this thread
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;

   private:
    std::unique_lock<std::mutex> lock_;
  };
};

}  // namespace ll::gpu
