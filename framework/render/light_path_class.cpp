#include "render/light_path_class.h"

namespace ll {

const char* lightPathClassName(LightPathClass c) { return effectName(lightPathClassEffect(c)); }

const char* lightPathClassShortName(LightPathClass c) {
  switch (c) {
    case LightPathClass::Emission: return "emission";
    case LightPathClass::DirectLighting: return "direct";
    case LightPathClass::MirrorReflection: return "mirror";
    case LightPathClass::Refraction: return "refraction";
    case LightPathClass::GlossyReflection: return "glossy";
    case LightPathClass::DiffuseInterreflection: return "indirect";
    case LightPathClass::Caustics: return "caustics";
    case LightPathClass::SkyLight: return "sky";
  }
  return "?";
}

const char* lightPathClassPattern(LightPathClass c) {
  switch (c) {
    case LightPathClass::Emission: return "L E";
    case LightPathClass::DirectLighting: return "L D E";
    case LightPathClass::MirrorReflection: return "L D? S+ E (reflections)";
    case LightPathClass::Refraction: return "L D? S+ E (a refraction)";
    case LightPathClass::GlossyReflection: return "L .* D G S* E";
    case LightPathClass::DiffuseInterreflection: return "L .* D D S* E";
    case LightPathClass::Caustics: return "L .* S D .* E";
    case LightPathClass::SkyLight: return "Lsky .* D .* E";
  }
  return "?";
}

Effect lightPathClassEffect(LightPathClass c) {
  switch (c) {
    case LightPathClass::Emission: return Effect::Emission;
    case LightPathClass::DirectLighting: return Effect::DirectLighting;
    case LightPathClass::MirrorReflection: return Effect::MirrorReflection;
    case LightPathClass::Refraction: return Effect::Refraction;
    case LightPathClass::GlossyReflection: return Effect::GlossyReflection;
    case LightPathClass::DiffuseInterreflection: return Effect::DiffuseInterreflection;
    case LightPathClass::Caustics: return Effect::Caustics;
    case LightPathClass::SkyLight: return Effect::SkyLight;
  }
  return Effect::DirectLighting;
}

LightPathState LightPathState::then(PathVertex v) const {
  LightPathState s = *this;
  const bool specular = v == PathVertex::SpecularReflection || v == PathVertex::SpecularRefraction;
  if (specular) {
    if (nonSpecular_ > 0) {
      s.caustic_ = true;
    } else {
      s.specularFirst_ = true;
      s.refractedFirst_ = refractedFirst_ || v == PathVertex::SpecularRefraction;
    }
  } else {
    if (nonSpecular_ == 0) s.firstGlossy_ = v == PathVertex::Glossy;
    if (nonSpecular_ < 2) ++s.nonSpecular_;
  }
  return s;
}

LightPathClass LightPathState::atLight(bool sky) const {
  if (sky && nonSpecular_ > 0) return LightPathClass::SkyLight;
  if (caustic_) return LightPathClass::Caustics;
  if (nonSpecular_ >= 2) return firstGlossy_ ? LightPathClass::GlossyReflection : LightPathClass::DiffuseInterreflection;
  if (specularFirst_) return refractedFirst_ ? LightPathClass::Refraction : LightPathClass::MirrorReflection;
  return nonSpecular_ == 0 ? LightPathClass::Emission : LightPathClass::DirectLighting;
}

uint8_t LightPathState::index() const {
  return static_cast<uint8_t>(nonSpecular_ | (firstGlossy_ << 2) | (specularFirst_ << 3) | (refractedFirst_ << 4) |
                              (caustic_ << 5));
}

LightPathMask LightPathState::reachable() const {
  // The states are few (6 bits): the classes reachable from each, by a fixed point over all events.
  struct Table {
    std::array<LightPathMask, 64> mask{};
    Table() {
      std::array<LightPathState, 64> states{};
      std::array<bool, 64> seen{};
      // Every state reachable from the eye's, and each one's class at a light.
      std::array<LightPathState, 64> work{};
      int n = 0;
      work[n++] = LightPathState{};
      seen[LightPathState{}.index()] = true;
      while (n > 0) {
        const LightPathState s = work[--n];
        states[s.index()] = s;
        mask[s.index()] = lightPathBit(s.atLight(false)) | lightPathBit(s.atLight(true));
        for (PathVertex v : {PathVertex::Diffuse, PathVertex::Glossy, PathVertex::SpecularReflection,
                             PathVertex::SpecularRefraction}) {
          const LightPathState t = s.then(v);
          if (!seen[t.index()]) {
            seen[t.index()] = true;
            work[n++] = t;
          }
        }
      }
      for (bool changed = true; changed;) {
        changed = false;
        for (int i = 0; i < 64; ++i) {
          if (!seen[static_cast<size_t>(i)]) continue;
          for (PathVertex v : {PathVertex::Diffuse, PathVertex::Glossy, PathVertex::SpecularReflection,
                               PathVertex::SpecularRefraction}) {
            const LightPathMask m = mask[static_cast<size_t>(i)] | mask[states[static_cast<size_t>(i)].then(v).index()];
            if (m != mask[static_cast<size_t>(i)]) {
              mask[static_cast<size_t>(i)] = m;
              changed = true;
            }
          }
        }
      }
    }
  };
  static const Table table;
  return table.mask[index()];
}

}  // namespace ll
