#include "scene/effects.h"

namespace ll {

const char* effectName(Effect e) {
  switch (e) {
    case Effect::DirectLighting: return "direct-lighting";
    case Effect::HardShadows: return "hard-shadows";
    case Effect::SoftShadows: return "soft-shadows";
    case Effect::MirrorReflection: return "mirror-reflection";
    case Effect::Refraction: return "refraction";
    case Effect::GlossyHighlights: return "glossy-highlights";
    case Effect::DiffuseInterreflection: return "diffuse-interreflection";
    case Effect::Textures: return "textures";
    case Effect::Emission: return "emission";
    case Effect::GlossyReflection: return "glossy-reflection";
    case Effect::SkyLight: return "sky-light";
    case Effect::Dispersion: return "dispersion";
    case Effect::Caustics: return "caustics";
  }
  return "?";
}

std::vector<std::string> EffectSet::names() const {
  std::vector<std::string> out;
  for (int i = 0; i < kEffectCount; ++i) {
    const auto e = static_cast<Effect>(1u << i);
    if (has(e)) out.emplace_back(effectName(e));
  }
  return out;
}

}  // namespace ll
