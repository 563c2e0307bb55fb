// Materials of the scene model: the lecture's Blinn-Phong terms plus mirror,
// dielectric and emission. All colours are linear RGB in [0, inf).
#pragma once

#include <memory>
#include <string>

#include "core/image.h"
#include "core/math.h"

namespace ll {

// A diffuse texture: an image (bilinear, repeating) or a procedural checker
// over uv in [0,1]^2. Multiplies (image) or replaces (checker) kd.
struct Texture {
  enum class Kind { None, Image, Checker };
  Kind kind = Kind::None;
  std::shared_ptr<const Image> image;
  Vec2 squares{8.0f};  // checker squares along u and v
  Rgb colorA{1.0f}, colorB{0.0f};

  Rgb eval(Vec2 uv) const;
};

struct Material {
  std::string name;
  Rgb ka{0.0f};            // ambient reflectance
  Rgb kd{0.0f};            // diffuse reflectance (albedo)
  Rgb ks{0.0f};            // specular reflectance of the Blinn-Phong highlight
  float shininess = 1.0f;  // Blinn-Phong exponent p
  Rgb mirror{0.0f};        // perfect mirror reflectance
  Rgb transmission{0.0f};  // dielectric transmittance
  float ior = 1.0f;        // index of refraction of the inside
  Rgb absorption{0.0f};    // Beer-Lambert coefficient, 1 / scene unit
  Rgb emission{0.0f};      // emitted radiance
  Texture texture;

  Rgb diffuse(Vec2 uv) const;
  bool emits() const { return !isBlack(emission); }
  bool reflectsMirror() const { return !isBlack(mirror); }
  bool transmits() const { return !isBlack(transmission); }
  bool glossy() const { return !isBlack(ks); }
};

}  // namespace ll
