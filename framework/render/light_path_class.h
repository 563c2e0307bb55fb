// Heckbert's light-path classes (Heckbert 1990, "Adaptive radiosity textures
// for bidirectional ray tracing"): a path from the light L to the eye E is
// written as its scattering events, D diffuse, G glossy (a rough microfacet
// surface), S specular (mirror or smooth glass). LightLab splits `path`'s
// estimate into a small fixed set of classes, one per effect the framework
// names (scene/effects.h), so that the classes add up to the picture and
// each one's share says how much that effect matters in this scene:
//
//   emission                L S* E  without S      the lights and the sky, seen directly
//   direct-lighting         L X E                   one bounce: the local model (X = D or G)
//   mirror-reflection       L X? S+ E, S reflect    Whitted's chains, through mirrors only
//   refraction              L X? S+ E, S refract    ... with at least one refraction
//   glossy-reflection       L .* X G S* E           the scene blurred in a rough surface
//   diffuse-interreflection L .* X D S* E           indirect diffuse light (radiosity's K^2 L_e, ...)
//   caustics                L .* S X .* E           light focused by mirrors or glass onto a surface
//   sky-light               Lsky .* X .* E          the sky lighting a surface (any path from the sky with a D or G)
//
// Every path lands in exactly one class: sky-light first (the light is the
// sky and the path scattered off a surface), then caustics, then the first
// of the others whose pattern it matches. Blinn-Phong's highlight lobe counts as D: it is the
// local model's, and radiosity and ray casting treat it as such.
#pragma once

#include <array>
#include <cstdint>

#include "scene/effects.h"

namespace ll {

enum class LightPathClass : uint8_t {
  Emission,
  DirectLighting,
  MirrorReflection,
  Refraction,
  GlossyReflection,
  DiffuseInterreflection,
  Caustics,
  SkyLight,
};
inline constexpr int kLightPathClassCount = 8;

const char* lightPathClassName(LightPathClass c);     // the effect's name, e.g. "direct-lighting"
const char* lightPathClassShortName(LightPathClass c);  // for labels in small tiles: "direct", "indirect", "sky"
const char* lightPathClassPattern(LightPathClass c);  // Heckbert's notation, e.g. "L D E"
Effect lightPathClassEffect(LightPathClass c);
inline LightPathClass lightPathClassAt(int i) { return static_cast<LightPathClass>(i); }

// A set of classes as bits (1 << class).
using LightPathMask = uint32_t;
inline constexpr LightPathMask kAllLightPathClasses = (1u << kLightPathClassCount) - 1u;
inline constexpr LightPathMask lightPathBit(LightPathClass c) { return 1u << static_cast<uint32_t>(c); }

// The kind of one scattering event.
enum class PathVertex : uint8_t { Diffuse, Glossy, SpecularReflection, SpecularRefraction };

// What a path's events so far (from the eye) say about its class: a few
// flags, so that a path tracer carries it at no cost.
class LightPathState {
 public:
  // The state after one more event, further from the eye.
  LightPathState then(PathVertex v) const;
  // The class of the path if a light ends it here (the sky: sky = true).
  LightPathClass atLight(bool sky = false) const;
  // The classes any continuation of this path (including ending at a light now) can reach.
  LightPathMask reachable() const;

 private:
  uint8_t nonSpecular_ = 0;  // D and G events so far, counted up to 2
  bool firstGlossy_ = false;  // the first D/G event was G
  bool specularFirst_ = false;  // an S event before the first D/G event
  bool refractedFirst_ = false;  // ... and one of those a refraction
  bool caustic_ = false;  // an S event after a D/G event
  uint8_t index() const;
};

}  // namespace ll
