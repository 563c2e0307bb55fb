// Which code runs for each task. In the solution tree every task is the
// solution, compiled in. In the student tree (LIGHTLAB_SOLUTION=OFF) each
// task's function is the student's, loaded from its task module, or the
// reference (the solution as object code), per task and at run time:
//   Auto       the student's; where its stub runs (LIGHTLAB_TODO) the
//              reference stands in for that call, the pixel is striped and
//              the task is reported as not implemented (the default);
//   Student    the student's only, stubs included: a task's own tests;
//   Reference  the reference (`--reference A2.3`, the GUI's task switches,
//              and every other task while one task is tested or graded).
#pragma once

#include <string>
#include <vector>

#include "tasks/visibility.h"

namespace ll::tasks {

enum class Mode : unsigned char { Auto, Student, Reference };

// Whether this build loads the tasks from modules (the student tree). In the
// solution tree the modes are recorded but every task is the solution.
LIGHTLAB_FRAMEWORK_ONLY bool modulesEnabled();

LIGHTLAB_FRAMEWORK_ONLY Mode mode(int task);
LIGHTLAB_FRAMEWORK_ONLY void setMode(int task, Mode m);
LIGHTLAB_FRAMEWORK_ONLY void setAllModes(Mode m);

// `owner` runs the student's code (Student), every other task its reference:
// how a test of one task runs, so that no other task's stub or bug shows in it.
LIGHTLAB_FRAMEWORK_ONLY void isolateTask(int owner);

// "A2.3,A2.5" (or "all", "none", "A2" for all of an assignment's tasks) in
// Reference mode, the others in Auto. Throws UserError naming the known IDs.
LIGHTLAB_FRAMEWORK_ONLY void useReferences(const std::string& list);

// The IDs in Reference mode, "A2.3,A2.5" (empty if none).
LIGHTLAB_FRAMEWORK_ONLY std::string referenceList();

// What happened where task `id`'s stub ran, for a message after "A6.4 not implemented: ... --":
// under --isolate the stub's own placeholder ("your stub ran (--isolate)"), else its reference
// answered ("its reference stood in"); then whether its pixels are striped (`striped`, where the
// caller stripes them) or the picture is the same (`sameImage`, a stub with an exact fallback).
LIGHTLAB_FRAMEWORK_ONLY std::string stubOutcome(const std::string& id, bool sameImage, bool striped = true);

}  // namespace ll::tasks
