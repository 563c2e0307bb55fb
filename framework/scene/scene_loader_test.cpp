#include "scene/scene_loader.h"

#include <algorithm>
#include <filesystem>
#include <cstdint>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.h"

#include "core/error.h"

namespace ll {
namespace {

namespace fs = std::filesystem;

const std::string kScenes = std::string(LIGHTLAB_DATA_DIR) + "/scenes";

using testing_support::contains;
using testing_support::errorOf;
bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// A folder of this process's own (test binaries may run concurrently, e.g.
// ctest -j), removed when the process exits.
std::string tempDir() {
  struct Folder {
    fs::path path = fs::path(testing::TempDir()) /
                    ("lightlab_scene_loader_test_" + std::to_string(std::random_device{}()));
    ~Folder() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  fs::create_directories(folder.path);
  return folder.path.string();
}

// The 1-based number of the first line of `path` containing `needle`.
int lineContaining(const std::string& path, const std::string& needle) {
  std::ifstream in(path);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (contains(line, needle)) return n;
  return 0;
}

// A valid scene around the given pieces (each a JSON fragment).
std::string sceneJson(const std::string& objects, const std::string& materials = R"({"grey": {"kd": [0.5, 0.5, 0.5]}})",
                      const std::string& camera = R"({"eye": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40})",
                      const std::string& lights = "[]") {
  return "{\n\"camera\": " + camera + ",\n\"materials\": " + materials + ",\n\"lights\": " + lights +
         ",\n\"objects\": " + objects + "\n}\n";
}

Scene parse(const std::string& text) { return parseJsonScene(text, "mem.json", tempDir()); }

// --- Bundled scenes ----------------------------------------------------------------

std::vector<std::string> bundledScenes() {
  std::vector<std::string> out;
  for (const auto& entry : fs::recursive_directory_iterator(kScenes)) {
    if (!entry.is_regular_file()) continue;
    const fs::path& p = entry.path();
    const std::string name = p.filename().string();
    if (contains(p.string(), "/tests/bad/") || contains(name, ".schema.")) continue;
    if (p.extension() == ".json" || p.extension() == ".obj") out.push_back(p.string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(SceneLoader, EveryBundledSceneLoads) {
  const std::vector<std::string> scenes = bundledScenes();
  EXPECT_GE(scenes.size(), 10u);
  bool sawObj = false;
  for (const std::string& path : scenes) {
    SCOPED_TRACE(path);
    Scene s;
    ASSERT_NO_THROW(s = loadScene(path));
    sawObj |= fs::path(path).extension() == ".obj";
    EXPECT_EQ(s.path, path);
    EXPECT_GT(s.geometry.primitiveCount(), 0u);
    EXPECT_FALSE(s.objects.empty());
    EXPECT_FALSE(s.materials.empty());
    EXPECT_TRUE(s.effects.has(Effect::DirectLighting) || s.effects.has(Effect::SkyLight)) << "every bundled scene is lit";
    EXPECT_GT(s.camera.width, 0);
    EXPECT_GT(s.camera.fovYDeg, 0.0f);
    EXPECT_LT(s.camera.fovYDeg, 180.0f);
    // Geometry invariants the accelerators rely on.
    const Geometry& g = s.geometry;
    EXPECT_EQ(g.triangleObject.size(), g.triangles.size());
    EXPECT_EQ(g.sphereObject.size(), g.spheres.size());
    EXPECT_TRUE(g.normals.empty() || g.normals.size() == g.positions.size());
    EXPECT_TRUE(g.uvs.empty() || g.uvs.size() == g.positions.size());
    for (const glm::uvec3& t : g.triangles) ASSERT_LT(maxComponent(Vec3(t)), static_cast<float>(g.positions.size()));
    for (const Vec3& p : g.positions) ASSERT_TRUE(isFinite(p));
    uint32_t total = 0;
    for (size_t o = 0; o < s.objects.size(); ++o) {
      const SceneObject& obj = s.objects[o];
      ASSERT_LT(obj.material, s.materials.size());
      for (uint32_t p = obj.firstPrim; p < obj.firstPrim + obj.primCount; ++p) ASSERT_EQ(g.objectOf(p), o);
      total += obj.primCount;
    }
    EXPECT_EQ(total, g.primitiveCount()) << "object ranges must cover every primitive once";
  }
  EXPECT_TRUE(sawObj);
}

TEST(SceneLoader, CornellBox) {
  const Scene s = loadScene(kScenes + "/cornell_box.json");
  EXPECT_EQ(s.geometry.triangleCount(), 32u);
  EXPECT_EQ(s.geometry.spheres.size(), 0u);
  EXPECT_TRUE(s.lights.empty());
  ASSERT_EQ(s.areaLights.size(), 1u);
  const AreaLight& light = s.areaLights[0];
  EXPECT_NEAR(light.area, 130.0f * 105.0f, 0.5f);  // 13650 mm^2
  EXPECT_EQ(light.prims.size(), 2u);
  EXPECT_EQ(s.objects[light.object].name, "light");
  EXPECT_NEAR(light.emission.r, 18.387f, 1e-4f);
  EXPECT_FLOAT_EQ(light.cdf.back(), light.area);
  EXPECT_TRUE(s.effects.has(Effect::SoftShadows));
  EXPECT_TRUE(s.effects.has(Effect::Emission));
  EXPECT_TRUE(s.effects.has(Effect::DiffuseInterreflection));
  EXPECT_FALSE(s.effects.has(Effect::HardShadows));
  EXPECT_FALSE(s.effects.has(Effect::Refraction));
  EXPECT_FALSE(s.effects.has(Effect::MirrorReflection));
  EXPECT_FALSE(s.effects.has(Effect::GlossyHighlights));
  EXPECT_FALSE(s.effects.has(Effect::Textures));
  EXPECT_FLOAT_EQ(s.camera.fovYDeg, 39.3076f);
  EXPECT_EQ(s.camera.eye, Vec3(278, 273, -800));
  // The light's normal points down, into the room.
  const glm::uvec3 t = s.geometry.triangles[light.prims[0]];
  const Vec3 n = glm::normalize(glm::cross(s.geometry.positions[t.y] - s.geometry.positions[t.x],
                                           s.geometry.positions[t.z] - s.geometry.positions[t.x]));
  EXPECT_NEAR(n.y, -1.0f, 1e-6f);
}

// Rough metals make glossy reflection possible, not mirror reflection: their mirror field is only the local
// model's specular limit (the path tracer's light-path classes count them as glossy). Whitted still traces it.
TEST(SceneLoader, RoughMetalsAreGlossyNotMirrors) {
  const Scene s = loadScene(kScenes + "/metal_spheres.json");
  EXPECT_TRUE(s.effects.has(Effect::GlossyReflection));
  EXPECT_FALSE(s.effects.has(Effect::MirrorReflection));
  EXPECT_FALSE(s.effects.has(Effect::Refraction));
  EXPECT_FALSE(s.effects.has(Effect::Caustics));  // L S+ D needs a smooth (specular) surface
  EXPECT_TRUE(s.hasMirrors);
  EXPECT_FALSE(s.hasTransmission);
  const Scene glass = loadScene(kScenes + "/glass_and_water.json");  // smooth water and glass, rough glass
  EXPECT_TRUE(glass.effects.has(Effect::Refraction));
  EXPECT_TRUE(glass.effects.has(Effect::GlossyReflection));
  EXPECT_TRUE(glass.hasTransmission);
}

TEST(SceneLoader, WhittedEffects) {
  const Scene s = loadScene(kScenes + "/whitted_1980.json");
  EXPECT_TRUE(s.effects.has(Effect::Refraction));
  EXPECT_TRUE(s.effects.has(Effect::MirrorReflection));
  EXPECT_TRUE(s.effects.has(Effect::HardShadows));
  EXPECT_TRUE(s.effects.has(Effect::Textures));
  EXPECT_FALSE(s.effects.has(Effect::SoftShadows));
  // Its light-blue background is a backdrop (lights_scene false): seen, lighting nothing.
  EXPECT_FALSE(s.effects.has(Effect::SkyLight));
  EXPECT_FALSE(s.environment.lightsScene());
  EXPECT_FALSE(s.environment.black());
  EXPECT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.geometry.spheres.size(), 3u);
  EXPECT_EQ(s.camera.width, 640);
  EXPECT_EQ(s.camera.height, 480);
}

TEST(SceneLoader, SinglePrimitiveScenesCannotShadow) {
  const Scene sphere = loadScene(kScenes + "/tests/sphere_point_light.json");
  EXPECT_FALSE(sphere.effects.has(Effect::HardShadows));
  EXPECT_TRUE(sphere.effects.has(Effect::DirectLighting));
  EXPECT_TRUE(sphere.effects.has(Effect::GlossyHighlights));
  const Scene quad = loadScene(kScenes + "/tests/shadow_quad.json");
  EXPECT_TRUE(quad.effects.has(Effect::HardShadows));
  const Scene fan = loadScene(kScenes + "/tests/triangle_fan.json");
  EXPECT_EQ(fan.geometry.triangleCount(), 8u);
  EXPECT_EQ(fan.geometry.normals.size(), 9u);
  EXPECT_EQ(fan.geometry.uvs.size(), 9u);
  ASSERT_EQ(fan.lights.size(), 1u);
  EXPECT_EQ(fan.lights[0].type, Light::Type::Directional);
  EXPECT_EQ(fan.lights[0].direction, Vec3(0, 0, -1));
}

TEST(SceneLoader, ObjSceneWithMaterials) {
  const Scene s = loadScene(kScenes + "/tests/obj_scene/cube.obj");
  EXPECT_GE(s.materials.size(), 2u);
  EXPECT_EQ(s.geometry.triangleCount(), 12u);
  const auto lamp = std::find_if(s.materials.begin(), s.materials.end(), [](const Material& m) { return m.emits(); });
  ASSERT_NE(lamp, s.materials.end());
  EXPECT_EQ(lamp->name, "lamp");
  EXPECT_EQ(lamp->emission, Rgb(5.0f));
  const auto blue = std::find_if(s.materials.begin(), s.materials.end(),
                                 [](const Material& m) { return m.name == "blue_plastic"; });
  ASSERT_NE(blue, s.materials.end());
  EXPECT_EQ(blue->kd, Rgb(0.2f, 0.3f, 0.8f));
  EXPECT_EQ(blue->ks, Rgb(0.5f));
  EXPECT_FLOAT_EQ(blue->shininess, 64.0f);
  // The top face (2 x 2) is the one area light; nothing else was added.
  ASSERT_EQ(s.areaLights.size(), 1u);
  EXPECT_NEAR(s.areaLights[0].area, 4.0f, 1e-5f);
  EXPECT_EQ(s.areaLights[0].prims.size(), 2u);
  EXPECT_TRUE(s.lights.empty());
  EXPECT_TRUE(s.effects.has(Effect::Emission));
  // Triangles per object: 10 blue, 2 lamp.
  std::vector<uint32_t> counts;
  for (const SceneObject& o : s.objects) counts.push_back(o.primCount);
  std::sort(counts.begin(), counts.end());
  EXPECT_EQ(counts, (std::vector<uint32_t>{2u, 10u}));
  // The camera frames the cube from +z.
  EXPECT_GT(s.camera.eye.z, 1.0f);
  EXPECT_NEAR(glm::length(s.camera.target), 0.0f, 1e-6f);
}

TEST(SceneLoader, LoadSceneRejectsMissingAndUnknownFiles) {
  const std::string missing = kScenes + "/nope.json";
  EXPECT_EQ(errorOf([&] { loadScene(missing); }), missing + ": no such scene file");
  const std::string txt = tempDir() + "/scene.txt";
  { std::ofstream(txt) << "{}"; }
  EXPECT_EQ(errorOf([&] { loadScene(txt); }), txt + ": unknown scene format '.txt' (allowed: .json, .obj)");
}

std::string writeFile(const std::string& name, const std::string& content);  // below

// Names longer than the system allows (ENAMETOOLONG) are a one-line error, never a filesystem_error
// (the scene-JSON fuzzer once ended the program on a texture path like this).
TEST(SceneLoader, NamesTooLongForTheSystemAreOneLineErrors) {
  const std::string longName(5000, 'x');
  EXPECT_TRUE(contains(errorOf([&] { loadScene(tempDir() + "/" + longName + ".json"); }), "cannot open scene file"));
  const std::string path = writeFile("long_texture.json",
                                     sceneJson("[]", R"({"grey": {"kd": [0.5, 0.5, 0.5], "texture": ")" + longName +
                                                         R"(.png"}})"));
  EXPECT_TRUE(contains(errorOf([&] { loadScene(path); }), "texture file not found")) << path;
}

// A scene saved in Latin-1 is one line that says so, without the raw byte.
TEST(SceneLoader, TextThatIsNotUtf8IsSaidToBeSo) {
  const std::string path = writeFile("latin1.json", "{\n\"description\": \"f\xfcr\",\n\"camera\": {}}");
  EXPECT_EQ(errorOf([&] { loadScene(path); }),
            path + ":2:18: malformed JSON: a byte that is not UTF-8 (the file was saved in another encoding, such as "
                   "Latin-1: save it as UTF-8)");
}

// A file too big is refused before a byte is read (a 2 GB file once took 36 s and 4.2 GB of memory
// to end in "unexpected end of input"); the error states the limit.
TEST(SceneLoader, FilesOverTheSizeLimitAreRefusedBeforeReading) {
  const std::string path = tempDir() + "/two_gigabytes.json";
  {
    std::ofstream(path, std::ios::binary) << "{";
  }
  fs::resize_file(path, 2ull << 30);  // sparse: no disk space, no time
  const std::string message = errorOf([&] { loadScene(path); });
  fs::remove(path);
  EXPECT_EQ(message, path + ": this scene file is 2.0 GB; LightLab reads a scene file of at most 64 MB (is it the right file?)");
  const std::string folder = tempDir() + "/folder.json";
  fs::create_directories(folder);
  EXPECT_EQ(errorOf([&] { loadScene(folder); }), folder + ": is a folder, not a scene file");
}

// A valid scene followed by NUL bytes (a file overwritten in place, a broken copy) was accepted:
// the JSON parser stops at the first NUL. Any NUL byte is an error at its line and column.
TEST(SceneLoader, NulBytesAfterAValidSceneAreAnErrorAtTheirPlace) {
  const std::string text = sceneJson("[]");
  const std::string path = writeFile("trailing_nul.json", text + std::string(4096, '\0'));
  const long lines = std::count(text.begin(), text.end(), '\n');
  const size_t lastLine = text.rfind('\n');
  const std::string column = std::to_string(text.size() - (lastLine == std::string::npos ? 0 : lastLine + 1) + 1);
  EXPECT_EQ(errorOf([&] { loadScene(path); }),
            path + ":" + std::to_string(lines + 1) + ":" + column +
                ": a NUL byte (0x00): a scene file is text, and this one holds binary data from here on");
  EXPECT_NO_THROW(loadScene(writeFile("no_nul.json", text)));
}

// --- Broken scene files: file:line:col and the hint --------------------------------

struct BadCase {
  const char* file;
  const char* lineNeedle;  // text on the line the error must point at
  int line, column;
  const char* message;     // what follows "path:line:col: "
};

TEST(SceneLoader, BadFilesPointAtTheRightLine) {
  const BadCase cases[] = {
      {"malformed_json.json", "\"fov_y_deg\"", 6, 5, "malformed JSON: "},
      {"unknown_key.json", "\"fovy\"", 6, 5,
       "unknown key 'fovy' in scene.camera (allowed: eye, target, up, fov_y_deg, width, height)"},
      {"wrong_type.json", "\"radius\"", 27, 7, "scene.objects[0].radius must be a number, got a string"},
      {"negative_radius.json", "\"radius\"", 27, 7, "scene.objects[0].radius must be > 0, got -1"},
      {"missing_mesh.json", "\"file\"", 26, 7, "mesh file not found: "},
      {"unknown_material.json", "\"gold\"", 25, 7, "unknown material 'gold' (defined: grey)"},
  };
  for (const BadCase& c : cases) {
    const std::string path = kScenes + "/tests/bad/" + c.file;
    SCOPED_TRACE(path);
    ASSERT_EQ(lineContaining(path, c.lineNeedle), c.line) << "test data changed";
    const std::string msg = errorOf([&] { loadScene(path); });
    const std::string where = path + ":" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": ";
    EXPECT_TRUE(startsWith(msg, where + c.message)) << msg;
    EXPECT_FALSE(contains(msg, "\n")) << msg;
  }
}

TEST(SceneLoader, BadFileHints) {
  const std::string bad = kScenes + "/tests/bad/";
  EXPECT_TRUE(contains(errorOf([&] { loadScene(bad + "malformed_json.json"); }), "missing comma"));
  // The mesh path is the absolute one that was tried.
  const std::string mesh = errorOf([&] { loadScene(bad + "missing_mesh.json"); });
  EXPECT_TRUE(contains(mesh, "mesh file not found: " + bad + "does_not_exist.ply")) << mesh;
  // An OBJ face naming a vertex the file does not have (found by the OBJ fuzzer: it read past the vertices).
  EXPECT_EQ(errorOf([&] { loadScene(bad + "obj_bad_index.obj"); }),
            bad + "obj_bad_index.obj: face 1 uses vertex 4, but the file has 3");
}

TEST(SceneLoader, EveryBadFileIsCovered) {
  // A new file in tests/bad/ must get a case above.
  int n = 0;
  for (const auto& entry : fs::directory_iterator(kScenes + "/tests/bad")) {
    EXPECT_THROW(loadScene(entry.path().string()), UserError) << entry.path();
    ++n;
  }
  EXPECT_EQ(n, 7);
}

// --- In-memory scenes: errors ------------------------------------------------------

TEST(SceneLoader, CameraUpParallelToView) {
  const std::string msg = errorOf([] {
    parse(sceneJson("[]", R"({"grey": {}})", R"({"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 0, 2], "fov_y_deg": 40})"));
  });
  EXPECT_TRUE(startsWith(msg, "mem.json:2:1: camera up is parallel to the view direction")) << msg;
  EXPECT_TRUE(contains(errorOf([] {
                         parse(sceneJson("[]", "{}", R"({"eye": [1, 2, 3], "target": [1, 2, 3], "fov_y_deg": 40})"));
                       }),
                       "camera target equals the eye"));
  EXPECT_TRUE(contains(errorOf([] {
                         parse(sceneJson("[]", "{}", R"({"eye": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 180})"));
                       }),
                       "fov_y_deg = 180 is out of range"));
}

TEST(SceneLoader, ZeroAreaEmitters) {
  const std::string lamp = R"({"lamp": {"emission": [5, 5, 5]}})";
  const std::string quad = errorOf([&] {
    parse(sceneJson(R"([{"type": "quad", "material": "lamp", "vertices": [[0,0,0], [1,0,0], [2,0,0], [3,0,0]]}])", lamp));
  });
  EXPECT_TRUE(startsWith(quad, "mem.json:")) << quad;
  EXPECT_TRUE(contains(quad, "zero area")) << quad;
  // Triangles that are all degenerate: the object cannot emit.
  const std::string tris = errorOf([&] {
    parse(sceneJson(R"([
  {"type": "sphere", "material": "lamp", "center": [0, 0, 0], "radius": 1},
  {"type": "triangles", "name": "sliver", "material": "lamp",
   "positions": [[0,0,0], [1,1,1], [2,2,2]], "indices": [[0, 1, 2]]}
])",
                    lamp));
  });
  EXPECT_TRUE(startsWith(tris, "mem.json:7:3: emissive object 'sliver' has zero area")) << tris;
}

TEST(SceneLoader, UnknownTypesListAllowed) {
  const std::string object = errorOf([] { parse(sceneJson(R"([{"type": "cube", "material": "grey"}])")); });
  EXPECT_TRUE(startsWith(object, "mem.json:5:14: unknown object type 'cube' (allowed: sphere, quad, polygon, triangles, mesh)"))
      << object;
  const std::string light = errorOf([] {
    parse(sceneJson("[]", R"({"grey": {}})", R"({"eye": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40})",
                    R"([{"type": "spot", "position": [0, 0, 1]}])"));
  });
  EXPECT_TRUE(contains(light, "unknown light type 'spot' (allowed: point, directional")) << light;
  const std::string material = errorOf([] {
    parse(sceneJson(R"([{"type": "sphere", "material": "gold", "center": [0,0,0], "radius": 1}])",
                    R"({"grey": {}, "red": {"kd": [1, 0, 0]}})"));
  });
  EXPECT_TRUE(contains(material, "unknown material 'gold' (defined: grey, red)")) << material;
  const std::string key = errorOf([] { parse(sceneJson("[]", R"({"grey": {"kdd": [1, 1, 1]}})")); });
  EXPECT_TRUE(contains(key, "unknown key 'kdd' in scene.materials.grey (allowed: ka, kd, ks, shininess")) << key;
  const std::string top = errorOf([] { parse("{\"camera\": {}, \"lights\": [], \"objectz\": []}"); });
  EXPECT_TRUE(contains(top, "unknown key 'objectz' in scene (allowed: description, source, camera")) << top;
}

TEST(SceneLoader, WrongVectorLengthAndTypes) {
  const std::string center = errorOf([] {
    parse(sceneJson(R"([{"type": "sphere", "material": "grey", "center": [0, 0], "radius": 1}])"));
  });
  EXPECT_TRUE(contains(center, "scene.objects[0].center must be an array of 3 numbers [x, y, z], got an array of 2"))
      << center;
  const std::string colour = errorOf([] { parse(sceneJson("[]", R"({"grey": {"kd": [0.5, -0.1, 0]}})")); });
  EXPECT_TRUE(contains(colour, "scene.materials.grey.kd must have every channel >= 0")) << colour;
  const std::string quad = errorOf([] {
    parse(sceneJson(R"([{"type": "quad", "material": "grey", "vertices": [[0,0,0], [1,0,0], [1,1,0]]}])"));
  });
  EXPECT_TRUE(contains(quad, "needs at least 4 points, got 3")) << quad;
  const std::string index = errorOf([] {
    parse(sceneJson(R"([{"type": "triangles", "material": "grey", "positions": [[0,0,0], [1,0,0], [0,1,0]], "indices": [[0, 1, 3]]}])"));
  });
  EXPECT_TRUE(contains(index, "scene.objects[0].indices[0][2] must be a vertex index in [0, 2]")) << index;
  const std::string width = errorOf([] {
    parse(sceneJson("[]", "{}", R"({"eye": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40, "width": 64.5})"));
  });
  EXPECT_TRUE(contains(width, "scene.camera.width must be an integer, got 64.5")) << width;
}

TEST(SceneLoader, TransformMatrixAndPartsAreExclusive) {
  const std::string msg = errorOf([] {
    parse(sceneJson(R"([{"type": "sphere", "material": "grey", "center": [0,0,0], "radius": 1,
  "transform": {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "translate": [1, 0, 0]}}])"));
  });
  EXPECT_TRUE(contains(msg, "takes either 'matrix' or scale/rotate_deg/translate, not both")) << msg;
  const std::string count = errorOf([] {
    parse(sceneJson(R"([{"type": "sphere", "material": "grey", "center": [0,0,0], "radius": 1, "transform": {"matrix": [1,0,0]}}])"));
  });
  EXPECT_TRUE(contains(count, "must be 16 numbers")) << count;
  const std::string zero = errorOf([] {
    parse(sceneJson(R"([{"type": "quad", "material": "grey", "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "transform": {"scale": [1, 0, 1]}}])"));
  });
  EXPECT_TRUE(contains(zero, "must be non-zero on every axis")) << zero;
  const std::string nonUniform = errorOf([] {
    parse(sceneJson(R"([{"type": "sphere", "material": "grey", "center": [0,0,0], "radius": 1, "transform": {"scale": [1, 2, 1]}}])"));
  });
  EXPECT_TRUE(contains(nonUniform, "spheres take only uniform scale")) << nonUniform;
}

// A sphere at 1e38 rendered black with no message, and a scene scaled to 1e38 was reported as
// "camera up is parallel to the view direction": both are overflow, said at the key.
TEST(SceneLoader, ValuesBeyondTheSceneLimitsAreReportedAsOverflow) {
  const std::string far = errorOf([] {
    parse(sceneJson(R"([{"type": "sphere", "material": "grey", "center": [1e38, 0, 0], "radius": 1}])"));
  });
  EXPECT_TRUE(contains(far, "mem.json:") && contains(far, ": object '") && contains(far, "reaches 1e+38 scene units: overflow"))
      << far;
  const std::string scaled = errorOf([] {
    parse(sceneJson(R"([{"type": "quad", "material": "grey", "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]],
  "transform": {"scale": 1e38}}])"));
  });
  EXPECT_TRUE(contains(scaled, "reaches 1e+38 scene units: overflow")) << scaled;
  const std::string eye = errorOf([] {
    parse(sceneJson("[]", R"({"grey": {"kd": [0.5, 0.5, 0.5]}})",
                    R"({"eye": [0, 0, 1e38], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 40})"));
  });
  EXPECT_TRUE(contains(eye, "eye reaches 1e+38 scene units: overflow")) << eye;
  const std::string light = errorOf([] {
    parse(sceneJson("[]", R"({"grey": {"kd": [0.5, 0.5, 0.5]}})",
                    R"({"eye": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40})",
                    R"([{"type": "point", "position": [0, -2e8, 0], "intensity": [1, 1, 1]}])"));
  });
  EXPECT_TRUE(contains(light, "reaches 2e+08 scene units: overflow")) << light;
  EXPECT_NO_THROW(parse(sceneJson(R"([{"type": "sphere", "material": "grey", "center": [9e7, 0, 0], "radius": 1e6}])")));
}

std::string writeFile(const std::string& name, const std::string& content) {
  const std::string path = tempDir() + "/" + name;
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

TEST(SceneLoader, MeshWithNaNCoordinateNamesTheFile) {
  const std::string path = writeFile("nan_vertex.off", "OFF\n3 1 0\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n");
  const std::string msg = errorOf([] {
    parse(sceneJson(R"([{"type": "mesh", "material": "grey", "file": "nan_vertex.off"}])"));
  });
  EXPECT_TRUE(startsWith(msg, "mem.json:5:")) << msg;
  EXPECT_TRUE(contains(msg, path)) << msg;
}

TEST(SceneLoader, BinaryMeshWithNaNCoordinateIsRejected) {
  // A binary STL with one triangle whose second vertex has z = NaN.
  std::string stl(80, ' ');
  stl.replace(0, 10, "binary stl");  // must not start with "solid"
  const uint32_t count = 1;
  stl.append(reinterpret_cast<const char*>(&count), sizeof(count));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float data[12] = {0, 0, 1, 0, 0, 0, 1, 0, nan, 0, 1, 0};
  stl.append(reinterpret_cast<const char*>(data), sizeof(data));
  stl.append(2, '\0');
  const std::string path = writeFile("nan_vertex.stl", stl);
  const std::string msg = errorOf([] {
    parse(sceneJson(R"([{"type": "mesh", "material": "grey", "file": "nan_vertex.stl"}])"));
  });
  EXPECT_TRUE(startsWith(msg, "mem.json:5:")) << msg;
  EXPECT_TRUE(contains(msg, path + ": vertex 1 has a non-finite coordinate")) << msg;
}

TEST(SceneLoader, ObjTooLargeIsOverflow) {
  // Coordinates so large the framing camera overflowed to inf (found by the OBJ fuzzer).
  const std::string huge = writeFile("huge.obj", "v -1 -1 -1\nv 1 -1 -1\nv -1 1.5e20 1\nf 1 2 3\n");
  EXPECT_EQ(errorOf([&] { loadScene(huge); }),
            huge + ": vertex 3 reaches 1.5e+20 units: overflow (a scene must stay within +-1e8 units; scale it down)");
  // At the limit, the framing camera (2.6 radii away) is still usable.
  const std::string big = writeFile("big.obj", "v -1e8 -1e8 -1e8\nv 1e8 -1e8 -1e8\nv -1e8 1e8 1e8\nf 1 2 3\n");
  EXPECT_NO_THROW(loadScene(big));
}

TEST(SceneLoader, EmptyMeshFileNamesTheFile) {
  const std::string path = writeFile("empty.off", "");
  const std::string msg = errorOf([] { parse(sceneJson(R"([{"type": "mesh", "material": "grey", "file": "empty.off"}])")); });
  EXPECT_TRUE(contains(msg, path)) << msg;
  const std::string noFaces = writeFile("no_faces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  const std::string msg2 = errorOf([] { parse(sceneJson(R"([{"type": "mesh", "material": "grey", "file": "no_faces.off"}])")); });
  EXPECT_TRUE(contains(msg2, noFaces)) << msg2;
  const std::string format = errorOf([] { parse(sceneJson(R"([{"type": "mesh", "material": "grey", "file": "m.3ds"}])")); });
  EXPECT_TRUE(contains(format, "unknown mesh format '.3ds' (allowed: .obj, .ply, .off, .stl)")) << format;
}

// --- In-memory scenes: what loads --------------------------------------------------

TEST(SceneLoader, DefaultsAndPrimitiveOrder) {
  const Scene s = parse(sceneJson(R"([
  {"type": "sphere", "material": "grey", "center": [0, 0, 0], "radius": 1},
  {"type": "quad", "name": "floor", "material": "grey", "vertices": [[-1,-1,0], [1,-1,0], [1,1,0], [-1,1,0]]},
  {"type": "polygon", "material": "grey", "vertices": [[0,0,1], [1,0,1], [1.5,1,1], [0.5,1.5,1], [-0.5,1,1]]}
])"));
  EXPECT_EQ(s.camera.up, Vec3(0, 1, 0));
  EXPECT_EQ(s.camera.width, 512);
  EXPECT_EQ(s.camera.height, 512);
  EXPECT_EQ(s.background, Rgb(0.0f));
  EXPECT_EQ(s.ambient, Rgb(0.0f));
  EXPECT_FLOAT_EQ(s.materials[0].shininess, 1.0f);
  EXPECT_FLOAT_EQ(s.materials[0].ior, 1.0f);
  EXPECT_EQ(s.path, "mem.json");
  // Triangles first (quad: 2, pentagon fan: 3), then the sphere.
  EXPECT_EQ(s.geometry.triangleCount(), 5u);
  ASSERT_EQ(s.geometry.spheres.size(), 1u);
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.objects[0].name, "sphere 0");
  EXPECT_EQ(s.objects[0].firstPrim, 5u);
  EXPECT_EQ(s.objects[0].primCount, 1u);
  EXPECT_EQ(s.objects[1].name, "floor");
  EXPECT_EQ(s.objects[1].firstPrim, 0u);
  EXPECT_EQ(s.objects[1].primCount, 2u);
  EXPECT_EQ(s.objects[2].firstPrim, 2u);
  EXPECT_EQ(s.objects[2].primCount, 3u);
  // Quad uvs at the corners, counter-clockwise winding from the front (+z).
  ASSERT_EQ(s.geometry.uvs.size(), s.geometry.positions.size());
  EXPECT_EQ(s.geometry.uvs[2], Vec2(1, 1));
  const glm::uvec3 t = s.geometry.triangles[0];
  const Vec3 n = glm::cross(s.geometry.positions[t.y] - s.geometry.positions[t.x],
                            s.geometry.positions[t.z] - s.geometry.positions[t.x]);
  EXPECT_GT(n.z, 0.0f);
  EXPECT_TRUE(s.effects.empty()) << "no lights, plain diffuse: no effect at all";
}

Vec3 firstVertex(const std::string& transform) {
  const Scene s = parse(sceneJson(R"([{"type": "quad", "material": "grey", "vertices": [[1,0,0], [1,1,0], [0,1,0], [0,0,0]],
  "transform": )" + transform + "}]"));
  return s.geometry.positions[0];
}

void expectNear(const Vec3& a, const Vec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(SceneLoader, TransformsApplyScaleRotateTranslateInOrder) {
  expectNear(firstVertex(R"({"translate": [1, 2, 3]})"), Vec3(2, 2, 3));
  expectNear(firstVertex(R"({"rotate_deg": [0, 90, 0]})"), Vec3(0, 0, -1));  // right-hand rule about +y
  expectNear(firstVertex(R"({"rotate_deg": [0, 0, 90]})"), Vec3(0, 1, 0));
  expectNear(firstVertex(R"({"scale": [2, 1, 1], "rotate_deg": [0, 0, 90], "translate": [0, 0, 5]})"), Vec3(0, 2, 5));
  expectNear(firstVertex(R"({"scale": 3})"), Vec3(3, 0, 0));
  // Row-major matrix, translation in the last column.
  expectNear(firstVertex(R"({"matrix": [0,-1,0,10, 1,0,0,0, 0,0,1,0, 0,0,0,1]})"), Vec3(10, 1, 0));
  // Euler order X first, then Y: scaled (0,2,0) -> Rx(90): (0,0,2) -> Ry(90): (2,0,0)
  // (Y first would give (0,0,2)).
  const Scene s = parse(sceneJson(R"([{"type": "sphere", "material": "grey", "center": [0, 1, 0], "radius": 0.5,
  "transform": {"rotate_deg": [90, 90, 0], "scale": 2}}])"));
  expectNear(s.geometry.spheres[0].center, Vec3(2, 0, 0));
  EXPECT_FLOAT_EQ(s.geometry.spheres[0].radius, 1.0f);
}

TEST(SceneLoader, NormalsTransformByInverseTranspose) {
  const Scene s = parse(sceneJson(R"([{"type": "triangles", "material": "grey",
  "positions": [[1,0,0], [0,1,0], [0,0,1]], "indices": [[0,1,2]],
  "normals": [[1,1,0], [1,1,0], [1,1,0]], "transform": {"scale": [2, 1, 1]}}])"));
  ASSERT_EQ(s.geometry.normals.size(), 3u);
  // A plane x + y = c scaled by 2 in x becomes x/2 + y = c: normal ~ (1/2, 1, 0).
  expectNear(s.geometry.normals[0], glm::normalize(Vec3(0.5f, 1.0f, 0.0f)));
}

TEST(SceneLoader, CheckerTextureAndLights) {
  const Scene s = parse(sceneJson(
      R"([{"type": "quad", "material": "floor", "vertices": [[-1,-1,0], [1,-1,0], [1,1,0], [-1,1,0]]},
          {"type": "sphere", "material": "floor", "center": [0,0,1], "radius": 0.5}])",
      R"({"floor": {"texture": {"type": "checker", "squares": [4, 2], "color_a": [1, 0, 0], "color_b": [0, 0, 1]}}})",
      R"({"eye": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40})",
      R"([{"type": "directional", "direction": [0, 0, -2], "intensity": [0.5, 0.5, 0.5]},
          {"type": "point", "position": [1, 2, 3]}])"));
  const Texture& tex = s.materials[0].texture;
  ASSERT_EQ(tex.kind, Texture::Kind::Checker);
  EXPECT_EQ(tex.squares, Vec2(4, 2));
  EXPECT_EQ(s.materials[0].diffuse(Vec2(0.1f, 0.1f)), Rgb(1, 0, 0));   // square (0,0): colour a
  EXPECT_EQ(s.materials[0].diffuse(Vec2(0.3f, 0.1f)), Rgb(0, 0, 1));   // square (1,0): colour b
  EXPECT_EQ(s.materials[0].diffuse(Vec2(0.3f, 0.6f)), Rgb(1, 0, 0));   // square (1,1): colour a
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].direction, Vec3(0, 0, -1));  // normalised
  EXPECT_EQ(s.lights[0].intensity, Rgb(0.5f));
  EXPECT_EQ(s.lights[1].type, Light::Type::Point);
  EXPECT_EQ(s.lights[1].intensity, Rgb(1.0f));  // default
  EXPECT_TRUE(s.effects.has(Effect::Textures));
  EXPECT_TRUE(s.effects.has(Effect::HardShadows));
}

}  // namespace
}  // namespace ll
