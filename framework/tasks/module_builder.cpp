#include "tasks/module_builder.h"

#include <regex>
#include <sstream>

#include "core/files.h"
#include "core/subprocess.h"
#include "tasks/task_catalog.h"

#ifndef LIGHTLAB_SOURCE_DIR
#define LIGHTLAB_SOURCE_DIR ""
#endif
#ifndef LIGHTLAB_BUILD_DIR
#define LIGHTLAB_BUILD_DIR ""
#endif
#ifndef LIGHTLAB_CMAKE_COMMAND
#define LIGHTLAB_CMAKE_COMMAND "cmake"
#endif

namespace ll::tasks {

namespace fs = std::filesystem;

namespace {

std::string relativeTo(const std::string& file, const std::string& root) {
  if (root.empty()) return file;
  std::error_code ec;
  const fs::path abs = fs::weakly_canonical(fs::path(file), ec);
  const fs::path base = fs::weakly_canonical(fs::path(root), ec);
  const std::string a = abs.string(), b = base.string() + "/";
  return a.rfind(b, 0) == 0 ? a.substr(b.size()) : file;
}

}  // namespace

std::string sourceRoot() { return LIGHTLAB_SOURCE_DIR; }
std::string buildRoot() { return LIGHTLAB_BUILD_DIR; }

TaskFileWatcher::TaskFileWatcher(const std::string& root) {
  const auto catalog = taskCatalog();
  for (size_t t = 0; t < catalog.size(); ++t) {
    const fs::path p = fs::path(root) / catalog[t].path();
    files_.push_back({static_cast<int>(t), p, writeTime(p)});
  }
}

std::vector<int> TaskFileWatcher::changed() {
  std::vector<int> tasks;
  for (Watched& w : files_) {
    const auto t = writeTime(w.path);
    if (t == w.time) continue;
    w.time = t;
    if (t != fs::file_time_type{}) tasks.push_back(w.task);  // deleted: nothing to build
  }
  return tasks;
}

std::string CompilerMessage::oneLine() const {
  std::ostringstream out;
  if (!file.empty()) {
    out << file;
    if (line > 0) out << ':' << line;
    if (column > 0) out << ':' << column;
    out << ": ";
  }
  out << text;
  return out.str();
}

CompilerMessage firstCompilerError(const std::string& log, const std::string& root) {
  static const std::regex located(R"(^(\S[^:]*):(\d+):(?:(\d+):)? (?:fatal error|error): (.*)$)");
  static const std::regex anyError(R"((^|[^A-Za-z])(error|Error|ERROR)\b)");
  std::istringstream in(log);
  std::string line, fallback;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::smatch m;
    if (std::regex_match(line, m, located)) {
      CompilerMessage e;
      e.file = relativeTo(m[1].str(), root);
      e.line = std::stoi(m[2].str());
      e.column = m[3].matched ? std::stoi(m[3].str()) : 0;
      e.text = m[4].str();
      return e;
    }
    if (fallback.empty() && line.rfind("FAILED:", 0) != 0 && std::regex_search(line, anyError)) fallback = line;
  }
  CompilerMessage e;
  e.text = fallback.empty() ? "the build failed (see its log)" : fallback;
  return e;
}

std::string moduleTarget(int task) {
  std::string key = taskCatalog()[static_cast<size_t>(task)].id;
  for (char& c : key)
    if (c == '.') c = '_';
  return "lightlab_task_" + key;
}

ModuleBuild buildTaskModules(const std::vector<int>& tasks, const std::string& buildDir, const std::string& root) {
  ModuleBuild b;
  b.tasks = tasks;
  ChildSpec spec;
  spec.argv = {LIGHTLAB_CMAKE_COMMAND, "--build", buildDir};
  for (int t : tasks) {
    spec.argv.push_back("--target");
    spec.argv.push_back(moduleTarget(t));
  }
  spec.env = {"LC_ALL=C"};  // the compiler's messages in ASCII (plain quotes), as the GUI's font draws them
  spec.timeoutSeconds = 600.0;
  const SubprocessResult r = runChild(spec);
  b.seconds = r.seconds;
  b.log = r.started ? r.output : r.error;
  b.ok = r.succeeded();
  if (!b.ok) {
    b.firstError = firstCompilerError(b.log, root);
    if (r.timedOut) b.firstError.text = "the build " + r.describe();
  }
  return b;
}

}  // namespace ll::tasks
