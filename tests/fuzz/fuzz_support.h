// What the loader fuzz targets share: a scratch folder of this process, and
// the promises a loaded scene keeps (finite geometry, a usable camera).
#pragma once

#include <cmath>
#include <cstdlib>
#include <string>

#include <unistd.h>

#include "scene/scene.h"

namespace ll::fuzz {

// An empty folder of this process under $TMPDIR (created once; run_fuzzer.sh points TMPDIR
// into its work folder, which it empties on the next run).
inline const std::string& scratchDir() {
  static const std::string dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/lightlab-fuzz-XXXXXX";
    if (!mkdtemp(pattern.data())) std::abort();
    return pattern;
  }();
  return dir;
}

// A scene that loaded must be renderable: finite positions and spheres, indices in range.
inline void checkScene(const Scene& s) {
  const Geometry& g = s.geometry;
  for (const Vec3& p : g.positions)
    if (!isFinite(p)) std::abort();
  for (const glm::uvec3& t : g.triangles)
    if (t.x >= g.positions.size() || t.y >= g.positions.size() || t.z >= g.positions.size()) std::abort();
  for (const Sphere& sp : g.spheres)
    if (!isFinite(sp.center) || !(sp.radius > 0.0f) || !std::isfinite(sp.radius)) std::abort();
  if (!isFinite(s.camera.eye) || !isFinite(s.camera.target) || !(s.camera.width > 0) || !(s.camera.height > 0))
    std::abort();
}

}  // namespace ll::fuzz
