// Task modules (the student tree): each task's file compiled into its own
// shared object, lightlab_<ID>.so -- the student's in <build>/modules, the
// references (the solution, object code only) in assignments/reference/lib
// (in the solution tree: <build>/modules/reference). A module is loaded on
// first use with RTLD_NOW | RTLD_LOCAL: its symbols stay its own, so no
// student symbol can replace a framework one, and its calls to other tasks'
// functions reach the framework's dispatch (task_function.h). Each module
// exports one entry, lightlab_task_function(name) -> the function's address,
// written by the build (cmake/task_module_entry.cpp.in).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tasks/visibility.h"

namespace ll::tasks {

// $LIGHTLAB_STUDENT_MODULES, else the build's modules folder.
LIGHTLAB_FRAMEWORK_ONLY std::string studentModuleDir();
// $LIGHTLAB_REFERENCE_MODULES, else the references this build was set up with.
LIGHTLAB_FRAMEWORK_ONLY std::string referenceModuleDir();
LIGHTLAB_FRAMEWORK_ONLY std::string modulePath(const std::string& dir, int task);

struct LoadedFunction {
  void* address = nullptr;
  std::string error;  // one line for the student when address is null
};

// Function `name` of `task` from the student's module or the reference.
// Thread-safe; a module is opened once per process.
LIGHTLAB_FRAMEWORK_ONLY LoadedFunction loadTaskFunction(int task, const std::string& name, bool reference);

// Hot reload (lightlab gui --watch): forgets every student module, so the next
// call of a task function loads the module as it is on disk now. Precondition:
// no student code is running or will return into an old module (the GUI stops
// every pane first). Each reloaded module is loaded from a private copy (the
// loader would return the old one for the same path or file), kept in
// $TMPDIR/lightlab-reload-<pid> until the process exits; old modules stay
// mapped. References are not reloaded.
LIGHTLAB_FRAMEWORK_ONLY void reloadStudentModules();
// How many times reloadStudentModules ran: TaskFunction re-resolves when it changes.
LIGHTLAB_FRAMEWORK_ONLY uint64_t studentModuleGeneration();

// What is wrong with a built module's exports, one line each (empty: nothing):
// symbols other than its entry (a student file defining a framework or grader
// function). Reads the file only; no student code runs.
LIGHTLAB_FRAMEWORK_ONLY std::vector<std::string> checkModuleExports(const std::string& path, int task);

// What is wrong when the module loads in this process (it runs the module's
// static initialisers: call it in a child process): a symbol it uses is
// defined nowhere or is framework-only, its entry or a function is missing.
LIGHTLAB_FRAMEWORK_ONLY std::vector<std::string> checkModuleLoads(const std::string& path, int task);

}  // namespace ll::tasks
