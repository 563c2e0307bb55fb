// Bilinear lookup of an image texture, repeating in both directions; texel
// (i, j) has its centre at uv ((i + 0.5) / width, 1 - (j + 0.5) / height), so
// v = 0 is the image's bottom row. What the ray tracers use for textures. It
// answers part of task A1.5, so the student tree holds it as object code only
// (tasks/framework_answer.h).
#pragma once

#include "core/image.h"
#include "core/math.h"

namespace ll {

Rgb bilinearLookup(const Image& image, Vec2 uv);

}  // namespace ll
