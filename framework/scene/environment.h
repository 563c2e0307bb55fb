// The light from beyond the scene: the lecture's "put a big sphere around
// the scene". Either a constant radiance or an equirectangular (longitude-
// latitude) HDR image, +y up: image column u = 0..1 runs once around y
// (u = 0.5 looks down -z, turned by `rotation`), row v = 0..1 from straight
// up to straight down. Radiance is looked up nearest-pixel, so the image is
// exactly the piecewise-constant function the sampler draws from.
//
// The path tracer samples it as a light (next-event estimation, combined
// with BSDF sampling by MIS): a constant sky uniformly over the sphere, an
// image by luminance x sin(theta) (pbrt's piecewise-constant 2D
// distribution, Pharr, Jakob and Humphreys, 4th ed., 2023). Ray casting and
// Whitted see it only where a ray leaves the scene.
#pragma once

#include <memory>
#include <vector>

#include "core/image.h"
#include "core/math.h"

namespace ll {

class Environment {
 public:
  Environment() = default;
  explicit Environment(const Rgb& constant) : color_(constant), average_(constant) {}
  // image: linear radiance; strength multiplies it; rotationDeg turns the sky about +y.
  Environment(std::shared_ptr<const Image> image, float strength, float rotationDeg);

  // Radiance arriving from direction dir (unit, pointing away from the scene). Finite, >= 0.
  Rgb radiance(const Vec3& dir) const;
  bool black() const { return image_ ? black_ : isBlack(color_); }
  // Whether the sky lights the scene (path samples it and counts it where a path escapes after a surface). False:
  // a backdrop, seen directly and in mirrors and glass but lighting nothing, as in Whitted's 1980 scene.
  bool lightsScene() const { return lightsScene_ && !black(); }
  void setLightsScene(bool on) { lightsScene_ = on; }
  bool isImage() const { return image_ != nullptr; }
  // Mean radiance over the sphere: what a technique that cannot look the sky up shows (the rasterizer's clear).
  Rgb average() const { return average_; }

  struct Sample {
    Vec3 dir{0.0f, 1.0f, 0.0f};  // unit, away from the scene
    Rgb radiance{0.0f};
    float pdf = 0.0f;  // per steradian
  };
  // u uniform in [0,1)^2. Precondition: !black().
  Sample sample(Vec2 u) const;
  // The density sample() draws dir with, per steradian.
  float pdf(const Vec3& dir) const;

 private:
  Vec2 toUv(const Vec3& dir) const;
  Vec3 fromUv(Vec2 uv) const;
  size_t pixelOf(Vec2 uv) const;

  Rgb color_{0.0f};
  std::shared_ptr<const Image> image_;
  float strength_ = 1.0f;
  float rotation_ = 0.0f;  // radians
  bool black_ = true;
  bool lightsScene_ = true;
  Rgb average_{0.0f};
  // Sampling: rows by marginal CDF, columns by each row's conditional CDF (each of size n + 1, from 0 to 1).
  std::vector<float> rowCdf_, columnCdf_;
  std::vector<float> weight_;  // luminance x sin(theta) per pixel
  double weightSum_ = 0.0;
};

}  // namespace ll
