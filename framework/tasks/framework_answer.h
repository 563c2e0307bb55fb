// The framework's own answers to student tasks -- the watertight triangle
// test answers A2.3, the careful sphere test A2.2, the reference camera A2.1,
// progressive refinement's shooting A5.3. The framework needs them (every
// accelerator tests triangles), the student tree must not hold their source,
// and a task's code must not use them. So:
//   - their bodies sit in regions  #if !LIGHTLAB_STUDENT_TREE ... #endif
//     (headers) or in whole answer files (LIGHTLAB_ANSWER_SOURCES in the top
//     CMakeLists.txt), which make_student_tree.sh strips;
//   - the solution tree compiles them as usual (inline where they are hot);
//   - for the student tree the build compiles them once more with
//     LIGHTLAB_EXPORT_ANSWERS (the header ones out of line, in
//     framework_answers.cpp): liblightlab_private.a, shipped as object code.
//     There each body starts with LIGHTLAB_ANSWER_GUARD, which reports a
//     violation when it runs inside the student code of the task it answers
//     (tasks/task_calls.h). The solution tree's copies carry no guard.
#pragma once

#ifdef LIGHTLAB_EXPORT_INLINE_ANSWERS  // framework_answers.cpp: the one out-of-line copy
#define LIGHTLAB_ANSWER_INLINE
#else
#define LIGHTLAB_ANSWER_INLINE inline
#endif

#ifdef LIGHTLAB_EXPORT_ANSWERS
#include "tasks/task_calls.h"
#include "tasks/task_catalog.h"
#define LIGHTLAB_ANSWER_GUARD(taskId, function)                          \
  do {                                                                  \
    static const int lightlabAnswered = ::ll::tasks::findTask(taskId);  \
    ::ll::tasks::answerUsed(lightlabAnswered, function);                \
  } while (0)
#else
#define LIGHTLAB_ANSWER_GUARD(taskId, function) ((void)0)
#endif
