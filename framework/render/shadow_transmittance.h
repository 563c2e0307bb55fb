// Filtered shadow rays: how much of a light reaches a point through the
// scene. An opaque surface blocks the light; a transmissive one tints it by
// its transmission colour (the ray does not bend: a shadow ray has a fixed
// end, the lecture's shortcut) and the media the ray passes through absorb
// it by Beer-Lambert, exp(-sigma d) over each segment of length d in a
// medium of coefficient sigma. Media nest as a refracted ray's do
// (render/media.h): leaving the glass inside water continues in water.
#pragma once

#include "core/math.h"
#include "core/ray.h"
#include "render/media.h"
#include "render/tracer.h"
#include "scene/scene.h"

namespace ll {

// Surfaces a shadow ray passes through before the light counts as blocked.
inline constexpr int kMaxShadowCrossings = 16;

// shadow: origin already offset off the surface, unit direction, tmax = distance to the light (kInfinity
// for a directional light). start: the media at the origin. Returns the transmittance in [0, 1] per channel.
Rgb filteredShadowTransmittance(const Scene& scene, const Tracer& tracer, const Ray& shadow, const Media& start);

}  // namespace ll
