// Fuzz target: an OBJ file with its MTL loaded as a scene (loadObjScene, through
// tinyobjloader). The input is the OBJ text, optionally followed by a line
// "#MTL" and the text of m.mtl, which `mtllib m.mtl` in the OBJ names.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/error.h"
#include "fuzz_support.h"
#include "scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string marker = "\n#MTL\n";
  const size_t split = input.find(marker);
  const std::string dir = ll::fuzz::scratchDir();
  std::ofstream(dir + "/m.obj", std::ios::binary) << input.substr(0, split);
  std::ofstream(dir + "/m.mtl", std::ios::binary)
      << (split == std::string::npos ? std::string() : input.substr(split + marker.size()));
  try {
    const ll::Scene scene = ll::loadObjScene(dir + "/m.obj");
    ll::fuzz::checkScene(scene);
  } catch (const ll::UserError&) {
  }
  return 0;
}
