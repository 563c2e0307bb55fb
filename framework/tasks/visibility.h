// Student code runs as task modules (shared objects, the student tree) that
// the framework's programs load; the programs export their symbols so that a
// module can call the framework. LIGHTLAB_FRAMEWORK_ONLY marks what a module
// must not reach (the task switches, the stub record the grader reads): it is
// hidden from dynamic linking, so a module naming it does not load.
#pragma once

#define LIGHTLAB_FRAMEWORK_ONLY __attribute__((visibility("hidden")))
