// Each light-path class's share of a finished render (a frame buffer that
// kept them, render/frame_buffer.h): `render --stats` and the GUI's panes.
#pragma once

#include <vector>

#include "render/frame_buffer.h"

namespace ll {

struct LightPathShare {
  LightPathClass cls = LightPathClass::Emission;
  double luminanceShare = 0.0;  // of the picture's luminance summed over pixels, 0..1
  // relMSE (image_metrics.h) of the picture without this class: mean over pixels and channels of
  // c^2 / (p^2 + 1e-2). With two passes or more c^2 is the product of the even and the odd passes'
  // independent estimates, so noise does not count as error; from one pass it includes the noise.
  double relMseWithout = 0.0;
};

// One entry per class, in class order; empty if the frame buffer kept no classes.
std::vector<LightPathShare> lightPathShares(const FrameBuffer& fb);

}  // namespace ll
