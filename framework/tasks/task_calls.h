// What student code does while it runs, per thread: which task's student
// function is running (the dispatcher marks it), whether its stub reported
// itself, and violations -- a task's code using the framework's own answer to
// that task (the watertight triangle test inside A2.3), or calling its own
// task function again. Violations are recorded with the render's task log
// and process-wide for the task tests, which fail the test.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "tasks/visibility.h"

namespace ll::tasks {

// While in scope, `task`'s student code runs on this thread. stubRan() tells
// whether its stub reported itself (LIGHTLAB_TODO) during the call, not
// counting the stubs of other tasks it called.
class LIGHTLAB_FRAMEWORK_ONLY StudentCall {
 public:
  explicit StudentCall(int task);
  ~StudentCall();
  StudentCall(const StudentCall&) = delete;
  StudentCall& operator=(const StudentCall&) = delete;
  bool stubRan() const;
  bool reentered() const { return reentered_; }  // the task's student code was already running here

 private:
  int task_;
  bool savedStub_;
  int savedInnermost_;
  bool reentered_;
};

// Whether `task`'s student code is running on this thread.
LIGHTLAB_FRAMEWORK_ONLY bool studentCodeRunning(int task);
// The task whose student code this thread runs innermost, or -1 (async-signal-safe: crash_report.h).
LIGHTLAB_FRAMEWORK_ONLY int innermostStudentTask();

// Called by the dispatch on every call of a task function (any mode): what a
// test uses, for the handouts' "builds on" lists, and in the render's task log
// whether the student's code or the reference answered (the GUI's pane label).
// Cheap after the first call per thread and render.
LIGHTLAB_FRAMEWORK_ONLY void noteTaskCalled(int task, bool byReference);
// The IDs of the tasks called since the last call, which clears the record.
LIGHTLAB_FRAMEWORK_ONLY std::vector<std::string> takeTasksCalled();

// Called by every stub report (render/student_task.h): the running call's stub ran, if the report is
// that call's task. Another task's report does not count: framework code that reports an exact
// fallback on every query (a BVH built while A4.1 was a stub) inside the student's A3.4 would
// otherwise make A3.4 look like a stub, and its reference re-run the whole subtree of rays at every
// bounce (2^depth the rays).
LIGHTLAB_FRAMEWORK_ONLY void noteStubRan(const char* id);

// A framework function that answers task `taskId` (the watertight triangle
// test answers A2.3) calls this first in the student tree: used from inside
// that task's student code, it is a violation.
LIGHTLAB_FRAMEWORK_ONLY void answerUsed(int task, const char* function);

// Records that `task`'s code broke a rule (message: what it did, for the student).
LIGHTLAB_FRAMEWORK_ONLY void reportViolation(int task, const std::string& message);

// Every violation since the last call, which clears the record: task ID -> message.
LIGHTLAB_FRAMEWORK_ONLY std::map<std::string, std::string> takeViolations();

}  // namespace ll::tasks
