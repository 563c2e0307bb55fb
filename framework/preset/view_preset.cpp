#include "preset/view_preset.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/files.h"
#include "core/params.h"
#include "modules/registry.h"
#include "scene/json_document.h"
#include "scene/scene_loader.h"

namespace ll {

namespace fs = std::filesystem;

namespace {

constexpr int kFormatVersion = 1;

// Reads {"name": value, ...} into `out`, checking each against `decls`.
std::map<std::string, std::string> parseParams(const JsonNode& node, const std::string& owner,
                                               const std::vector<ParamDecl>& decls) {
  node.requireObject();
  ParamSet check(owner, decls);
  std::map<std::string, std::string> out;
  for (auto it = node.json().begin(); it != node.json().end(); ++it) {
    const JsonNode value = node.child(it.key());
    std::string text;
    if (value.json().is_string())
      text = value.json().get<std::string>();
    else if (value.json().is_number() || value.json().is_boolean())
      text = value.json().dump();
    else
      value.fail(value.what() + " must be a string, number or boolean");
    try {
      check.set(it.key(), text);
    } catch (const UserError& e) {
      value.fail(e.what());
    }
    out[it.key()] = text;
  }
  return out;
}

template <class Info>
const Info& findNamed(const JsonNode& node, const std::string& key,
                      const Info& (*find)(const std::string&)) {
  const std::string name = node.string(key);
  try {
    return find(name);
  } catch (const UserError& e) {
    node.child(key).fail(e.what());
  }
}

PaneSetup parsePane(const JsonNode& n) {
  n.requireObject();
  n.allowOnly({"technique", "accelerator", "params", "accel_params", "spp", "view", "label"});
  PaneSetup p;
  const TechniqueInfo& t = findNamed<TechniqueInfo>(n, "technique", &findTechnique);
  p.technique = t.name;
  if (n.has("accelerator"))
    p.accelerator = findNamed<AcceleratorInfo>(n, "accelerator", &findAccelerator).name;
  const AcceleratorInfo& a = findAccelerator(p.accelerator);
  if (n.has("params"))
    p.techniqueParams = parseParams(n.child("params"), "technique '" + t.name + "'", t.params);
  if (n.has("accel_params"))
    p.accelParams = parseParams(n.child("accel_params"), "accelerator '" + a.name + "'", a.params);
  p.spp = n.integer("spp", p.spp, 1, 1 << 16);
  if (n.has("view")) {
    p.view = n.string("view");
    if (p.view != "image" && p.view != "nodes" && p.view != "primitives" && p.view != "light-paths")
      n.child("view").fail("unknown view '" + p.view + "' (allowed: image, nodes, primitives, light-paths)");
  }
  if (n.has("label")) {  // read from the back of a hall: a few words
    p.label = n.string("label");
    size_t chars = 0;
    for (const char c : p.label) chars += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1 : 0;
    if (chars < 1 || chars > 24 || p.label.find('\n') != std::string::npos)
      n.child("label").fail("a pane label is 1 to 24 characters on one line (got " + std::to_string(chars) + ")");
  }
  return p;
}

template <class Enum, size_t N>
Enum parseChoice(const JsonNode& n, const std::string& key, Enum fallback,
                 const std::pair<const char*, Enum> (&names)[N]) {
  if (!n.has(key)) return fallback;
  const std::string text = n.string(key);
  std::vector<std::string> allowed;
  for (const auto& [name, value] : names) {
    if (text == name) return value;
    allowed.emplace_back(name);
  }
  n.child(key).fail("unknown " + key + " '" + text + "' (allowed: " + joinNames(allowed) + ")");
}

constexpr std::pair<const char*, CompareMode> kModes[] = {{"side-by-side", CompareMode::SideBySide},
                                                          {"wipe", CompareMode::Wipe},
                                                          {"difference", CompareMode::Difference}};
constexpr std::pair<const char*, DiffMode> kDiffModes[] = {{"absolute", DiffMode::Absolute},
                                                           {"relative", DiffMode::Relative}};

nlohmann::json vec3Json(const Vec3& v) {
  return nlohmann::json::array({v.x, v.y, v.z});
}

}  // namespace

const char* compareModeName(CompareMode mode) {
  for (const auto& [name, value] : kModes)
    if (value == mode) return name;
  return "?";
}

ViewPreset parsePreset(const std::string& text, const std::string& file,
                       const std::string& baseDir, bool embedded) {
  const JsonDocument doc(text, file);
  const JsonNode root(doc, doc.root(), "", "preset");
  root.requireObject();
  const bool tagged = root.has("lightlab_preset");
  if ((!embedded || tagged) && (!tagged || root.json()["lightlab_preset"] != kFormatVersion))
    root.fail("not a LightLab view preset: it needs \"lightlab_preset\": " +
              std::to_string(kFormatVersion) +
              " (is this a scene? open scenes with `lightlab gui SCENE`)");
  root.allowOnly({"lightlab_preset", "description", "scene", "camera", "width", "height", "panes",
                  "pane_count", "compare", "ui_scale", "exposure", "structure", "inspect", "plot"});

  ViewPreset p;
  if (root.has("description")) p.description = root.string("description");
  const std::string scene = root.string("scene");
  const fs::path scenePath(scene);
  p.scene =
      scenePath.is_absolute() ? scene : (fs::path(baseDir) / scenePath).lexically_normal().string();
  if (root.has("camera")) p.camera = parseCamera(root.child("camera"));
  p.width = root.integer("width", 0, 0, 16384);
  p.height = root.integer("height", 0, 0, 16384);
  p.exposure = root.number("exposure", 0.0f, -20.0f, 20.0f);
  p.uiScale = root.number("ui_scale", 1.0f, 0.5f, 4.0f);
  p.showPlot = root.boolean("plot", false);
  if (root.has("structure")) {
    const JsonNode st = root.child("structure");
    st.requireObject();
    st.allowOnly({"show", "depth"});
    p.showStructure = st.boolean("show", true);
    p.structureDepth = st.integer("depth", 3, 0, 64);
  }

  if (root.has("inspect")) {  // {"pane": 0, "pixel": [x, y]}: that pixel's ray tree
    const JsonNode in = root.child("inspect");
    in.requireObject();
    in.allowOnly({"pane", "pixel"});
    p.inspectPane = in.integer("pane", 0, 0, kMaxPanes - 1);
    const JsonNode px = in.child("pixel");
    px.requireArray();
    if (px.size() != 2) px.fail("pixel must be [x, y]");
    p.inspectPixel = Vec2(std::floor(px.at(0).asNumber()) + 0.5f, std::floor(px.at(1).asNumber()) + 0.5f);
  }

  const JsonNode panes = root.child("panes");
  panes.requireArray();
  if (panes.size() < 1 || panes.size() > static_cast<size_t>(kMaxPanes))
    panes.fail("panes must list 1 to " + std::to_string(kMaxPanes) + " panes, got " +
               std::to_string(panes.size()));
  for (size_t i = 0; i < panes.size(); ++i) p.panes.push_back(parsePane(panes.at(i)));
  p.paneCount = static_cast<int>(p.panes.size()) == 3 ? 4 : static_cast<int>(p.panes.size());
  if (root.has("pane_count")) {
    p.paneCount = root.integer("pane_count", 2, 1, kMaxPanes);
    if (p.paneCount == 3) root.child("pane_count").fail("pane_count must be 1, 2 or 4");
  }
  while (static_cast<int>(p.panes.size()) < kMaxPanes) p.panes.push_back(p.panes.back());

  if (root.has("compare")) {
    const JsonNode c = root.child("compare");
    c.requireObject();
    c.allowOnly({"mode", "wipe", "a", "b", "diff", "diff_max", "reference"});
    p.compare.mode = parseChoice(c, "mode", p.compare.mode, kModes);
    p.compare.wipe = c.number("wipe", 0.5f, 0.0f, 1.0f);
    p.compare.paneA = c.integer("a", 0, 0, kMaxPanes - 1);
    p.compare.paneB = c.integer("b", 1, 0, kMaxPanes - 1);
    p.compare.diff = parseChoice(c, "diff", p.compare.diff, kDiffModes);
    p.compare.diffMax = c.number("diff_max", 0.0f, 0.0f, 1e9f);
    p.compare.reference = c.integer("reference", -1, -1, kMaxPanes - 1);
  }
  return p;
}

ViewPreset loadPreset(const std::string& path) {
  return parsePreset(readTextFile(path, "preset file"), path, fs::path(path).parent_path().string());
}

nlohmann::json presetToJson(const ViewPreset& p, const std::string& baseDir) {
  using nlohmann::json;
  json j;
  j["lightlab_preset"] = kFormatVersion;
  if (!p.description.empty()) j["description"] = p.description;
  std::string scene = p.scene;
  if (!scene.empty()) {  // relative to the preset's folder, so presets move with the tree
    const fs::path base =
        fs::absolute(baseDir.empty() ? fs::current_path() : fs::path(baseDir)).lexically_normal();
    const fs::path relative = fs::absolute(scene).lexically_normal().lexically_relative(base);
    if (!relative.empty()) scene = relative.string();
  }
  j["scene"] = scene;
  if (p.camera) {
    j["camera"] = {{"eye", vec3Json(p.camera->eye)},
                   {"target", vec3Json(p.camera->target)},
                   {"up", vec3Json(p.camera->up)},
                   {"fov_y_deg", p.camera->fovYDeg}};
  }
  if (p.width > 0) j["width"] = p.width;
  if (p.height > 0) j["height"] = p.height;
  j["exposure"] = p.exposure;
  j["ui_scale"] = p.uiScale;
  j["pane_count"] = p.paneCount;
  j["structure"] = {{"show", p.showStructure}, {"depth", p.structureDepth}};
  if (p.showPlot) j["plot"] = true;
  if (p.inspectPane >= 0)
    j["inspect"] = {{"pane", p.inspectPane},
                    {"pixel", {static_cast<int>(p.inspectPixel.x), static_cast<int>(p.inspectPixel.y)}}};
  j["panes"] = json::array();
  for (int i = 0; i < static_cast<int>(p.panes.size()) && i < kMaxPanes; ++i) {
    const PaneSetup& pane = p.panes[static_cast<size_t>(i)];
    json pj{{"technique", pane.technique},
            {"accelerator", pane.accelerator},
            {"spp", pane.spp},
            {"view", pane.view}};
    pj["params"] = pane.techniqueParams;
    pj["accel_params"] = pane.accelParams;
    if (!pane.label.empty()) pj["label"] = pane.label;
    j["panes"].push_back(pj);
  }
  j["compare"] = {{"mode", compareModeName(p.compare.mode)},
                  {"wipe", p.compare.wipe},
                  {"a", p.compare.paneA},
                  {"b", p.compare.paneB},
                  {"diff", p.compare.diff == DiffMode::Absolute ? "absolute" : "relative"},
                  {"diff_max", p.compare.diffMax},
                  {"reference", p.compare.reference}};
  return j;
}

void savePreset(const ViewPreset& preset, const std::string& path) {
  std::ofstream out(path);
  if (!out) throwUserError(path + ": cannot write preset file");
  out << presetToJson(preset, fs::path(path).parent_path().string()).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
}

}  // namespace ll
