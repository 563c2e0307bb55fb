// The framework's side of one task function in the student tree. Each call
// runs the student's function (from the task's module) or the reference, as
// the task's mode says (task_modes.h). The assignments' aN_dispatch.cpp
// define the functions of aN_tasks.h with it, so every caller -- the
// techniques, the tests, and the student's other tasks -- goes through it:
//
//   Ray cameraRay(const Camera& camera, float px, float py) {
//     static const tasks::TaskFunction<decltype(cameraRay)> f("A2.1", "cameraRay");
//     return f(camera, px, py);
//   }
//
// Auto: where the student's stub reports itself, the reference answers that
// call (the stub's result is dropped). Student: the student's result, stub or
// not. A student function that calls its own task function again (which in a
// graded run is itself, never the reference) is stopped with a violation,
// except for recursive tasks (A3.4 traces through the framework).
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <stdexcept>
#include <string>

#include "render/student_task.h"
#include "tasks/crash_guard.h"
#include "tasks/task_calls.h"
#include "tasks/task_catalog.h"
#include "tasks/task_modes.h"
#include "tasks/task_modules.h"

namespace ll::tasks {

template <typename Signature>
class TaskFunction;

template <typename R, typename... A>
class TaskFunction<R(A...)> {
 public:
  using Fn = R (*)(A...);

  TaskFunction(const char* id, const char* name)
      : task_(requireTask(id)), id_(id), name_(name), recursive_(taskCatalog()[static_cast<size_t>(task_)].recursive) {}

  R operator()(A... args) const {
    const Mode m = mode(task_);
    noteTaskCalled(task_, m == Mode::Reference);
    if (m == Mode::Reference) return reference()(args...);
    const Fn fn = student();
    if (!fn) return m == Mode::Auto ? reference()(args...) : R{};
    R result{};
    bool stub = false;
    {
      StudentCall call(task_);
      if (call.reentered() && !recursive_) {
        reportViolation(task_, std::string("your ") + name_ + " calls " + name_ +
                                   " (the task's own function) again: in a graded run that is your own code, never the reference");
        stub = true;
      } else {
        const bool guarded = crashGuardEnabled();  // the GUI: a crash or a NaN storm stops the render, naming the task
        if (guarded)
          result = guardedCall(id_, name_, [&] { return fn(args...); });
        else
          result = fn(args...);
        stub = call.stubRan();
        if (guarded && !stub && holdsNaN(result)) noteNaNResult(task_, id_, name_);
      }
    }
    if (stub && m == Mode::Auto) return reference()(args...);
    return result;
  }

 private:
  // The student's function of the current module generation (hot reload re-resolves it).
  Fn student() const {
    const uint64_t generation = studentModuleGeneration();
    if (loadedGeneration_.load(std::memory_order_acquire) != generation) {
      std::lock_guard lock(studentMutex_);
      if (loadedGeneration_.load(std::memory_order_relaxed) != generation) {
        const LoadedFunction f = loadTaskFunction(task_, name_, false);
        student_.store(reinterpret_cast<Fn>(f.address), std::memory_order_relaxed);
        studentError_ = f.error;
        loadedGeneration_.store(generation, std::memory_order_release);
      }
    }
    const Fn fn = student_.load(std::memory_order_relaxed);
    if (!fn) reportMissingTask(id_, studentError_.c_str());  // the module does not load: said once per render
    return fn;
  }

  Fn reference() const {
    Fn fn = reference_.load(std::memory_order_acquire);
    if (fn) return fn;
    const LoadedFunction f = loadTaskFunction(task_, name_, true);
    if (!f.address) throw std::runtime_error("the reference of " + std::string(id_) + " does not load: " + f.error);
    fn = reinterpret_cast<Fn>(f.address);
    reference_.store(fn, std::memory_order_release);
    return fn;
  }

  int task_;
  const char* id_;
  const char* name_;
  bool recursive_;
  mutable std::atomic<Fn> student_{nullptr}, reference_{nullptr};
  // The module generation student_ belongs to (none yet: ~0); written under studentMutex_.
  mutable std::atomic<uint64_t> loadedGeneration_{~uint64_t{0}};
  mutable std::mutex studentMutex_;
  mutable std::string studentError_;  // why the module does not load (written under studentMutex_)
};

}  // namespace ll::tasks
