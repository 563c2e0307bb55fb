#include "tasks/module_builder.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "tasks/task_catalog.h"

namespace ll::tasks {
namespace {

namespace fs = std::filesystem;

TEST(ModuleBuilder, FirstCompilerErrorIsTheFirstLocatedError) {
  const std::string log =
      "[1/3] Building CXX object assignments/CMakeFiles/lightlab_task_A2_4.dir/a2_raycasting/blinn_phong.cpp.o\n"
      "FAILED: assignments/CMakeFiles/lightlab_task_A2_4.dir/a2_raycasting/blinn_phong.cpp.o\n"
      "/home/s/lightlab/assignments/a2_raycasting/blinn_phong.cpp: In function 'll::Rgb ll::a2::blinnPhong(...)':\n"
      "/home/s/lightlab/assignments/a2_raycasting/blinn_phong.cpp:14:3: error: expected ';' before 'return'\n"
      "   14 |   return Rgb(0.0f)\n"
      "/home/s/lightlab/assignments/a2_raycasting/blinn_phong.cpp:20:1: error: second error\n";
  const CompilerMessage e = firstCompilerError(log, "/home/s/lightlab");
  EXPECT_EQ(e.file, "assignments/a2_raycasting/blinn_phong.cpp");
  EXPECT_EQ(e.line, 14);
  EXPECT_EQ(e.column, 3);
  EXPECT_EQ(e.text, "expected ';' before 'return'");
  EXPECT_EQ(e.oneLine(), "assignments/a2_raycasting/blinn_phong.cpp:14:3: expected ';' before 'return'");
}

TEST(ModuleBuilder, FatalErrorsAndPathsOutsideTheTree) {
  const CompilerMessage e = firstCompilerError("/usr/include/x.h:2:10: fatal error: y.h: No such file\n", "/src");
  EXPECT_EQ(e.file, "/usr/include/x.h");
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.text, "y.h: No such file");
}

TEST(ModuleBuilder, UnlocatedErrorsFallBackToTheFirstLineSayingError) {
  const CompilerMessage e = firstCompilerError(
      "FAILED: modules/lightlab_A2.4.so\n/usr/bin/ld: blinn_phong.cpp.o: undefined reference to `foo()'\n"
      "collect2: error: ld returned 1 exit status\n",
      "/src");
  EXPECT_EQ(e.line, 0);
  EXPECT_EQ(e.text, "collect2: error: ld returned 1 exit status");
  EXPECT_EQ(firstCompilerError("nothing useful\n", "/src").text, "the build failed (see its log)");
}

TEST(ModuleBuilder, TargetsAreNamedByTask) {
  EXPECT_EQ(moduleTarget(requireTask("A2.4")), "lightlab_task_A2_4");
}

TEST(ModuleBuilder, TheWatcherReportsTheTaskWhoseFileChanged) {
  const fs::path root = fs::temp_directory_path() / "lightlab_watcher_test";
  fs::remove_all(root);
  const auto catalog = taskCatalog();
  for (const TaskInfo& info : catalog) {
    fs::create_directories((root / info.path()).parent_path());
    std::ofstream(root / info.path()) << "// stub\n";
  }
  TaskFileWatcher watcher(root.string());
  EXPECT_TRUE(watcher.changed().empty());
  const int task = requireTask("A2.4");
  const fs::path file = root / catalog[static_cast<size_t>(task)].path();
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
  EXPECT_EQ(watcher.changed(), std::vector<int>{task});
  EXPECT_TRUE(watcher.changed().empty());  // reported once
  fs::remove(file);
  EXPECT_TRUE(watcher.changed().empty());  // a deleted file has nothing to build
  fs::remove_all(root);
}

}  // namespace
}  // namespace ll::tasks
