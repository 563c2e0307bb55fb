// The light-transport effects a scene calls for, and that a technique
// simulates. A technique spawns only the rays its scene's effects need.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ll {

enum class Effect : uint32_t {
  DirectLighting = 1u << 0,          // light reaching a surface straight from a light
  HardShadows = 1u << 1,             // point or directional lights that something can occlude
  SoftShadows = 1u << 2,             // area lights (emissive geometry) that something can occlude
  MirrorReflection = 1u << 3,        // a material with mirror reflectance
  Refraction = 1u << 4,              // a material that transmits
  GlossyHighlights = 1u << 5,        // a Blinn-Phong specular term lit by a light
  DiffuseInterreflection = 1u << 6,  // light bouncing between diffuse surfaces
  Textures = 1u << 7,                // a material with a texture
  Emission = 1u << 8,                // visible emissive surfaces
  GlossyReflection = 1u << 9,        // a rough metal or rough glass: the scene reflected blurred (microfacet BSDF)
  SkyLight = 1u << 10,               // the background lights the scene (a sky colour or HDR image around it)
  Dispersion = 1u << 11,             // glass whose index depends on wavelength (Cauchy): white light splits
  Caustics = 1u << 12,               // light focused by a mirror or glass onto a diffuse surface (L S+ D)
};
constexpr int kEffectCount = 13;

class EffectSet {
 public:
  constexpr EffectSet() = default;
  constexpr EffectSet(std::initializer_list<Effect> effects) {
    for (Effect e : effects) bits_ |= static_cast<uint32_t>(e);
  }
  constexpr bool has(Effect e) const { return (bits_ & static_cast<uint32_t>(e)) != 0; }
  constexpr void add(Effect e) { bits_ |= static_cast<uint32_t>(e); }
  constexpr bool contains(EffectSet other) const { return (bits_ & other.bits_) == other.bits_; }
  constexpr EffectSet minus(EffectSet other) const { return fromBits(bits_ & ~other.bits_); }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr uint32_t bits() const { return bits_; }
  static constexpr EffectSet fromBits(uint32_t b) {
    EffectSet s;
    s.bits_ = b;
    return s;
  }
  std::vector<std::string> names() const;

 private:
  uint32_t bits_ = 0;
};

const char* effectName(Effect e);  // kebab-case, e.g. "soft-shadows"

}  // namespace ll
