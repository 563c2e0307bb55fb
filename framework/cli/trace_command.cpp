// lightlab trace SCENE (--pixel X Y | --ray OX OY OZ DX DY DZ) [-t ..] [-a ..] [--json]
// Prints the closest hit of one ray: t, object, primitive, barycentrics,
// position, normals and material; with --pixel and a technique that traces
// (-t raycast: the camera ray and its shadow rays with each light's term;
// -t whitted: the recursion), also the ray tree of the pixel's sample.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/scene_setup.h"
#include "cli/task_lines.h"
#include "core/error.h"
#include "render/student_task.h"
#include "tasks/task_modes.h"

namespace ll::cli {

namespace {

struct TraceOptions {
  std::string scene, technique = "raycast", accelerator = "none";
  std::vector<float> pixel, ray;
  std::vector<std::string> sets;
  int width = 0, height = 0;
  bool json = false;
};

nlohmann::json vec(const Vec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json treeJson(const RayTree& tree) {
  nlohmann::json nodes = nlohmann::json::array();
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    const RayTreeNode& n = tree.nodes[i];
    nlohmann::json j = {{"id", i},
                        {"parent", n.parent},
                        {"kind", std::string(kRayKindNames[static_cast<size_t>(n.kind)])},
                        {"depth", n.depth},
                        {"origin", vec(n.origin)},
                        {"direction", vec(n.direction)},
                        {"throughput", vec(n.throughput)}};
    if (n.kind == RayKind::Shadow) {
      j["light_transmittance"] = vec(n.shadowTransmittance);
      if (!isBlack(n.contribution)) j["contribution"] = vec(n.contribution);  // raycast: the light's shading term
    } else if (!n.intersected) {
      j["traced"] = false;  // stopped by the depth or weight limit
    } else if (!n.hit) {
      j["hit"] = nullptr;  // the background: what it adds to the pixel, as a hit's contribution
      j["contribution"] = vec(n.throughput * n.radiance);
    } else {
      j["hit"] = {{"t", n.t},
                  {"position", vec(n.position)},
                  {"normal", vec(n.normal)},
                  {"object", n.object},
                  {"material", n.material},
                  {"entering", n.entering},
                  {"n1", n.n1},
                  {"n2", n.n2},
                  {"absorption", vec(n.absorption)}};
      if (n.fresnel) j["fresnel"] = {{"reflected", *n.fresnel}, {"transmitted", 1.0f - *n.fresnel}};
      if (n.totalInternalReflection) j["total_internal_reflection"] = true;
      j["local"] = vec(n.local);
      j["contribution"] = vec(n.contribution);
    }
    if (n.kind != RayKind::Shadow) j["radiance"] = vec(n.radiance);
    nodes.push_back(j);
  }
  return {{"pixel_radiance", vec(tree.pixel)}, {"nodes", nodes}};
}

// One line per node, indented by depth.
void printTree(const RayTree& tree) {
  std::vector<int> indent(tree.nodes.size(), 0);
  std::printf("ray tree (pixel radiance %.4g %.4g %.4g):\n", static_cast<double>(tree.pixel.r),
              static_cast<double>(tree.pixel.g), static_cast<double>(tree.pixel.b));
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    const RayTreeNode& n = tree.nodes[i];
    indent[i] = n.parent < 0 ? 0 : indent[static_cast<size_t>(n.parent)] + 1;
    std::printf("%*s%s", 2 * indent[i] + 2, "", std::string(kRayKindNames[static_cast<size_t>(n.kind)]).c_str());
    if (n.kind == RayKind::Shadow && isBlack(n.contribution))
      std::printf(": light %s\n", isBlack(n.shadowTransmittance) ? "blocked" : "visible");
    else if (n.kind == RayKind::Shadow)  // raycast: the light's Blinn-Phong term is this ray's share
      std::printf(": light visible, contributes %.4g\n", static_cast<double>(maxComponent(n.contribution)));
    else if (!n.intersected)
      std::printf(": not traced (depth or weight limit)\n");
    else if (!n.hit)
      std::printf(": background, weight %.3g, contributes %.4g\n", static_cast<double>(maxComponent(n.throughput)),
                  static_cast<double>(maxComponent(n.throughput * n.radiance)));
    else {
      // Where the ray enters or leaves glass: the indices on both sides and the Fresnel split.
      char fresnel[96] = "";
      if (n.fresnel)
        std::snprintf(fresnel, sizeof fresnel, ", n %.3g -> %.3g, Fresnel %.3g reflected", static_cast<double>(n.n1),
                      static_cast<double>(n.n2), static_cast<double>(*n.fresnel));
      std::printf(": %s (%s) at t = %.4g, weight %.3g, contributes %.4g%s%s\n", n.object.c_str(), n.material.c_str(),
                  static_cast<double>(n.t), static_cast<double>(maxComponent(n.throughput)),
                  static_cast<double>(maxComponent(n.contribution)), fresnel,
                  n.totalInternalReflection ? ", total internal reflection" : "");
    }
  }
}

}  // namespace

Command addTraceCommand(CLI::App& app, const GlobalOptions&) {
  auto o = std::make_shared<TraceOptions>();
  CLI::App* cmd = app.add_subcommand("trace", "Trace one ray (through a pixel or given explicitly) and print its hit");
  cmd->add_option("scene", o->scene, "Scene file (.json or .obj)")->required();
  auto* pixel = cmd->add_option("--pixel", o->pixel, "Pixel X Y (0,0 = top-left); the ray goes through its centre")
                    ->expected(2);
  auto* rayOption = cmd->add_option("--ray", o->ray, "Ray origin and direction OX OY OZ DX DY DZ (world space)")
                  ->expected(6);
  pixel->excludes(rayOption);
  cmd->add_option("-t,--technique", o->technique, "Technique (recursive ones print the ray tree)")
      ->capture_default_str();
  cmd->add_option("-a,--accel", o->accelerator, "Accelerator")->capture_default_str();
  cmd->add_option("--width", o->width, "Image width for --pixel (default: the scene camera's)");
  cmd->add_option("--height", o->height, "Image height for --pixel (default: the scene camera's)");
  cmd->add_option("--set", o->sets, "Technique or accelerator parameter, name=value (repeatable)");
  cmd->add_flag("--json", o->json, "Print JSON");
  return [o]() {
    if (o->pixel.empty() && o->ray.empty()) throwUserError("trace: give --pixel X Y or --ray OX OY OZ DX DY DZ");
    // The student tasks the trace runs, for the same "not implemented" lines a render prints.
    TaskLog tasks;
    const ScopedTaskLog logged(&tasks);
    SceneSetup s = setUpScene(o->scene, o->technique, o->accelerator, o->sets);
    Camera camera = s.scene.camera;
    if (o->width > 0) camera.width = o->width;
    if (o->height > 0) camera.height = o->height;
    Ray ray;
    nlohmann::json query;
    if (!o->pixel.empty()) {
      const float x = o->pixel[0], y = o->pixel[1];
      if (x < 0 || y < 0 || x >= static_cast<float>(camera.width) || y >= static_cast<float>(camera.height))
        throwUserError("trace: pixel (" + std::to_string(static_cast<int>(x)) + ", " +
                       std::to_string(static_cast<int>(y)) + ") is outside the " + std::to_string(camera.width) +
                       "x" + std::to_string(camera.height) + " image");
      ray = referenceCameraRay(camera, CameraFrame(camera), std::floor(x) + 0.5f, std::floor(y) + 0.5f);
      query = {{"pixel", {static_cast<int>(x), static_cast<int>(y)}}, {"width", camera.width}, {"height", camera.height}};
    } else {
      ray.origin = Vec3(o->ray[0], o->ray[1], o->ray[2]);
      ray.dir = Vec3(o->ray[3], o->ray[4], o->ray[5]);
      if (!(glm::length(ray.dir) > 0.0f)) throwUserError("trace: the ray direction must be non-zero");
    }
    QueryCounters counters;
    Hit hit;
    const bool found = s.accel->intersect(ray, hit, counters);
    nlohmann::json out = {{"scene", o->scene},
                          {"technique", s.technique->name},
                          {"accelerator", s.accelInfo->name},
                          {"query", query},
                          {"ray", {{"origin", vec(ray.origin)}, {"direction", vec(ray.dir)}, {"kind", "camera"}}},
                          {"nodes_visited", counters.nodesVisited},
                          {"primitives_tested", counters.primitivesTested}};
    if (found) {
      const SurfacePoint sp = s.scene.surfacePoint(ray, hit);
      const SceneObject& obj = s.scene.objects[sp.object];
      out["hit"] = {{"t", hit.t},
                    {"object", obj.name},
                    {"object_id", sp.object},
                    {"primitive", hit.prim},
                    {"primitive_kind", s.scene.geometry.isTriangle(hit.prim) ? "triangle" : "sphere"},
                    {"barycentrics", {1.0f - hit.b1 - hit.b2, hit.b1, hit.b2}},
                    {"position", vec(sp.position)},
                    {"geometric_normal", vec(sp.geometricNormal)},
                    {"shading_normal", vec(sp.shadingNormal)},
                    {"uv", {sp.uv.x, sp.uv.y}},
                    {"material", sp.material->name},
                    {"front_face", glm::dot(sp.geometricNormal, ray.dir) < 0.0f}};
    } else {
      out["hit"] = nullptr;
    }
    // Recursive techniques add the ray tree of the pixel's sample.
    std::optional<RayTree> tree;
    if (!o->pixel.empty() && !s.technique->gpu) {
      RenderSettings settings;
      settings.width = camera.width;
      settings.height = camera.height;
      const RenderContext ctx{s.scene, *s.accel, s.techniqueParams, settings, nullptr};
      const auto technique = s.technique->make();
      technique->prepare(ctx);
      tree = technique->rayTree(ctx, Vec2(std::floor(o->pixel[0]) + 0.5f, std::floor(o->pixel[1]) + 0.5f));
      if (tree) out["ray_tree"] = treeJson(*tree);
    }
    if (o->json) {
      std::cout << out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else if (found) {
      std::printf("hit %s (object %u, %s %u) at t = %g\n  position %s\n  normal   %s\n  material %s\n",
                  out["hit"]["object"].get<std::string>().c_str(), out["hit"]["object_id"].get<unsigned>(),
                  out["hit"]["primitive_kind"].get<std::string>().c_str(), hit.prim, static_cast<double>(hit.t),
                  out["hit"]["position"].dump().c_str(), out["hit"]["geometric_normal"].dump().c_str(),
                  out["hit"]["material"].get<std::string>().c_str());
    } else {
      std::printf("miss (the ray leaves the scene)\n");
    }
    if (tree && !o->json) printTree(*tree);
    // On stderr, as render's: the stubs this ray (tree) ran, and whose answer it shows.
    printTaskLines(tasks.missing(), tasks.exact(), false, tasks.violations(), tasks::referenceList());
  };
}

}  // namespace ll::cli
