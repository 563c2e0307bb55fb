// Fuzz target: the scene JSON loader (parseJsonScene) on arbitrary text. Every
// input must give a scene or a UserError; files it names resolve against an
// empty folder, so meshes and textures fail as "not found" quickly.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "fuzz_support.h"
#include "scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const ll::Scene scene = ll::parseJsonScene(text, "fuzz.json", ll::fuzz::scratchDir());
    ll::fuzz::checkScene(scene);
  } catch (const ll::UserError&) {
  }
  return 0;
}
