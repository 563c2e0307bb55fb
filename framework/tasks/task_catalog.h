// The student tasks of every assignment (A1.1 ... A6.4) as their grading
// specs (assignments/*/grading.json) list them: ID, title, the one file the
// student edits and the functions it defines. Generated at configure time
// (cmake/LightlabTasks.cmake), so the build, the dispatch and the grader
// read one list.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ll::tasks {

struct TaskInfo {
  const char* id;         // "A2.3"
  const char* title;      // "ray-triangle intersection"
  const char* folder;     // "a2_raycasting" (under assignments/)
  const char* file;       // "ray_triangle.cpp": the student's file
  const char* functions;  // "rayTriangle" (comma-separated, in ll::a2)
  bool recursive;         // the task calls itself through the framework (A3.4's trace)

  std::string assignment() const { return std::string(id).substr(0, std::string(id).find('.')); }  // "A2"
  std::string path() const { return std::string("assignments/") + folder + "/" + file; }
  std::vector<std::string> functionNames() const;
};

std::span<const TaskInfo> taskCatalog();

// The index of `id` in taskCatalog(), or -1.
int findTask(std::string_view id);

// The index of `id`; throws UserError listing the known IDs if there is none.
int requireTask(std::string_view id);

// The owning task of a GoogleTest suite name: "A2_3_RayTriangle" -> "A2.3",
// also behind a parameter prefix ("A6/A6_1_Furnace"). -1 for suites that
// test the framework rather than one task (A2_Raycast, A4_Accelerators).
int taskOfTestSuite(std::string_view suite);

}  // namespace ll::tasks
