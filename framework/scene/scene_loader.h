// Scene files: the JSON format of data/scenes/README.md, or an OBJ file with
// its MTL loaded directly. Every error is a UserError of one line that names
// the file, line and column and what was expected.
#pragma once

#include <string>

#include "scene/json_document.h"
#include "scene/scene.h"

namespace ll {

// A camera object as scene files write it (eye, target, up, fov_y_deg,
// width, height); presets use the same format. Fails at the node's position.
Camera parseCamera(const JsonNode& node);

// Loads by extension: .json (LightLab scene) or .obj (OBJ + MTL as a scene).
Scene loadScene(const std::string& path);

// The JSON loader on text in memory; relative paths resolve against baseDir.
// `file` is used in messages only.
Scene parseJsonScene(const std::string& text, const std::string& file, const std::string& baseDir);

// An OBJ file with its materials as a scene: Kd/Ka/Ks/Ns/Ni/Ke/Tf/illum/map_Kd
// mapped onto the material model, one point light at the eye, and a camera
// that frames the bounds.
Scene loadObjScene(const std::string& path);

}  // namespace ll
