#include "grading/grading_spec.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/error.h"
#include "scene/json_document.h"

namespace ll::grading {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The entry of references/<dir>/references.json whose "image" is <image>.
void resolveReference(const JsonNode& test, TestSpec& t, const std::string& dataDir) {
  const auto slash = t.reference.find('/');
  if (slash == std::string::npos)
    test.child("reference").fail("reference must be <folder>/<image> under data/references, e.g. a2/cornell_box.hdr");
  const std::string manifest = dataDir + "/references/" + t.reference.substr(0, slash) + "/references.json";
  if (!fs::exists(manifest)) test.child("reference").fail("no " + manifest);
  const JsonDocument doc = JsonDocument::load(manifest);
  t.technique = doc.root().at("technique").get<std::string>();
  std::vector<std::string> images;
  for (const auto& e : doc.root().at("references")) {
    images.push_back(e.at("image").get<std::string>());
    if (images.back() == t.reference.substr(slash + 1)) t.entry = e;
  }
  if (t.entry.is_null())
    test.child("reference").fail("no reference image '" + t.reference.substr(slash + 1) + "' in " + manifest +
                                 " (allowed: " + joinNames(images) + ")");
}

}  // namespace

GradingSpec loadGradingSpec(const std::string& path, const std::string& dataDir) {
  const JsonDocument doc = JsonDocument::load(path);
  const JsonNode root(doc, doc.root(), "", "grading spec");
  root.requireObject();
  root.allowOnly({"assignment", "title", "description", "tasks"});
  GradingSpec spec;
  spec.path = path;
  spec.assignment = root.string("assignment");
  spec.title = root.string("title");
  const auto strings = [](const JsonNode& node, const std::string& what) {
    node.requireArray();
    std::vector<std::string> out;
    for (size_t i = 0; i < node.size(); ++i) {
      if (!node.at(i).json().is_string()) node.at(i).fail(what + " lists names (strings)");
      out.push_back(node.at(i).json().get<std::string>());
    }
    return out;
  };
  const JsonNode tasks = root.child("tasks");
  tasks.requireArray();
  for (size_t i = 0; i < tasks.size(); ++i) {
    const JsonNode task = tasks.at(i);
    task.requireObject();
    task.allowOnly({"id", "title", "points", "file", "functions", "recursive", "forbidden", "uses", "tests",
                    "optional"});
    TaskSpec t;
    t.id = task.string("id");
    if (t.id.rfind(spec.assignment + ".", 0) != 0) task.child("id").fail("task IDs start with '" + spec.assignment + ".'");
    t.title = task.string("title");
    t.points = task.number("points", 0.0f, 1000.0f);
    t.optional = task.boolean("optional", false);
    t.file = task.string("file");
    t.functions = strings(task.child("functions"), "functions");
    if (task.has("forbidden")) t.forbidden = strings(task.child("forbidden"), "forbidden");
    if (task.has("uses")) t.uses = strings(task.child("uses"), "uses");
    const JsonNode tests = task.child("tests");
    tests.requireArray();
    if (tests.size() == 0) tests.fail("a task needs at least one test");
    for (size_t k = 0; k < tests.size(); ++k) {
      const JsonNode test = tests.at(k);
      test.requireObject();
      TestSpec s;
      s.kind = test.string("kind");
      s.weight = test.number("weight", 1.0f, 0.0f, 1000.0f);
      if (s.kind == "unit") {
        test.allowOnly({"kind", "weight", "filter"});
        if (test.has("filter")) s.filter = test.string("filter");
      } else if (s.kind == "image") {
        test.allowOnly({"kind", "weight", "reference"});
        s.reference = test.string("reference");
        resolveReference(test, s, dataDir);
      } else if (s.kind == "complexity") {
        test.allowOnly({"kind", "weight", "accelerator", "small", "large", "max_ratio"});
        s.accelerator = test.string("accelerator");
        s.small = test.string("small");
        s.large = test.string("large");
        s.maxRatio = test.number("max_ratio", 8.0f, 1.0f, 1e6f);
      } else {
        test.child("kind").fail("unknown test kind '" + s.kind + "' (allowed: unit, image, complexity)");
      }
      t.tests.push_back(std::move(s));
    }
    spec.tasks.push_back(std::move(t));
  }
  return spec;
}

std::string GradingSpec::folder() const { return fs::path(path).parent_path().string(); }

std::vector<std::string> GradingSpec::studentFiles() const {
  std::vector<std::string> out;
  for (const TaskSpec& t : tasks) out.push_back(t.file);
  return out;
}

std::vector<std::string> findGradingSpecs(const std::string& assignmentsDir) {
  std::vector<std::string> out;
  if (!fs::is_directory(assignmentsDir)) return out;
  for (const auto& e : fs::directory_iterator(assignmentsDir))
    if (fs::exists(e.path() / "grading.json")) out.push_back((e.path() / "grading.json").string());
  std::sort(out.begin(), out.end());
  return out;
}

GradingSpec findGradingSpec(const std::string& name, const std::string& assignmentsDir, const std::string& dataDir) {
  if (name.size() > 5 && name.substr(name.size() - 5) == ".json") {
    if (!fs::exists(name)) throwUserError(name + ": no such grading spec");
    return loadGradingSpec(name, dataDir);
  }
  std::vector<std::string> known;
  for (const std::string& path : findGradingSpecs(assignmentsDir)) {
    GradingSpec spec = loadGradingSpec(path, dataDir);
    const std::string folder = fs::path(path).parent_path().filename().string();
    if (lower(spec.assignment) == lower(name) || folder == name) return spec;
    known.push_back(spec.assignment + " (" + folder + ")");
  }
  throwUserError("unknown assignment '" + name + "' (allowed: " + joinNames(known) + ")");
}

}  // namespace ll::grading
