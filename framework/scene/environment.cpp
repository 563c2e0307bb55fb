#include "scene/environment.h"

#include <algorithm>
#include <cmath>

namespace ll {

namespace {

// The index i with cdf[i] <= u < cdf[i + 1] (cdf increasing from 0 to 1, size n + 1).
size_t findInterval(const float* cdf, size_t n, float u) {
  const float* it = std::upper_bound(cdf, cdf + n + 1, u);
  const auto i = static_cast<size_t>(std::max<std::ptrdiff_t>(0, (it - cdf) - 1));
  return std::min(i, n - 1);
}

}  // namespace

Environment::Environment(std::shared_ptr<const Image> image, float strength, float rotationDeg)
    : image_(std::move(image)), strength_(strength), rotation_(radians(rotationDeg)) {
  const int w = image_->width(), h = image_->height();
  weight_.resize(static_cast<size_t>(w) * static_cast<size_t>(h));
  glm::dvec3 radianceSum(0.0);
  double solidAngle = 0.0;
  for (int y = 0; y < h; ++y) {
    const double sinTheta = std::sin((y + 0.5) * kPiD / h);
    for (int x = 0; x < w; ++x) {
      Rgb c = image_->at(x, y) * strength_;
      if (!isFinite(c)) c = Rgb(0.0f);
      c = glm::max(c, Rgb(0.0f));
      radianceSum += glm::dvec3(c) * sinTheta;
      solidAngle += sinTheta;
      weight_[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)] =
          static_cast<float>(static_cast<double>(luminance(c)) * sinTheta);
    }
  }
  average_ = Rgb(radianceSum / std::max(solidAngle, 1e-30));
  // A small floor keeps every direction with radiance sampleable (MIS needs pdf > 0 wherever light is).
  double total = 0.0;
  for (float v : weight_) total += static_cast<double>(v);
  black_ = !(total > 0.0);
  const double floor = 1e-4 * total / static_cast<double>(weight_.size());
  const auto W = static_cast<size_t>(w), H = static_cast<size_t>(h);
  for (size_t y = 0; y < H; ++y) {
    const double sinTheta = std::sin((static_cast<double>(y) + 0.5) * kPiD / h);
    for (size_t x = 0; x < W; ++x) weight_[y * W + x] += static_cast<float>(floor * sinTheta);
  }
  rowCdf_.assign(H + 1, 0.0f);
  columnCdf_.assign(H * (W + 1), 0.0f);
  std::vector<double> rowSum(H, 0.0);
  for (size_t y = 0; y < H; ++y) {
    double sum = 0.0;
    float* cdf = &columnCdf_[y * (W + 1)];
    for (size_t x = 0; x < W; ++x) {
      sum += static_cast<double>(weight_[y * W + x]);
      cdf[x + 1] = static_cast<float>(sum);
    }
    for (size_t x = 1; x <= W; ++x)
      cdf[x] = sum > 0.0 ? static_cast<float>(static_cast<double>(cdf[x]) / sum)
                         : static_cast<float>(x) / static_cast<float>(W);
    cdf[W] = 1.0f;
    rowSum[y] = sum;
    weightSum_ += sum;
  }
  double running = 0.0;
  for (size_t y = 0; y < H; ++y) {
    running += rowSum[y];
    rowCdf_[y + 1] = weightSum_ > 0.0 ? static_cast<float>(running / weightSum_) : static_cast<float>(y + 1) / h;
  }
  rowCdf_[H] = 1.0f;
}

Vec2 Environment::toUv(const Vec3& dir) const {
  const float theta = std::acos(std::clamp(dir.y, -1.0f, 1.0f));
  float phi = std::atan2(dir.x, -dir.z) - rotation_;  // 0 looking down -z
  float u = phi / (2.0f * kPi) + 0.5f;
  u -= std::floor(u);
  return {u, theta / kPi};
}

Vec3 Environment::fromUv(Vec2 uv) const {
  const float phi = (uv.x - 0.5f) * 2.0f * kPi + rotation_, theta = uv.y * kPi;
  const float sinTheta = std::sin(theta);
  return {sinTheta * std::sin(phi), std::cos(theta), -sinTheta * std::cos(phi)};
}

size_t Environment::pixelOf(Vec2 uv) const {
  const int w = image_->width(), h = image_->height();
  const int x = std::clamp(static_cast<int>(uv.x * static_cast<float>(w)), 0, w - 1);
  const int y = std::clamp(static_cast<int>(uv.y * static_cast<float>(h)), 0, h - 1);
  return static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
}

Rgb Environment::radiance(const Vec3& dir) const {
  if (!image_) return color_;
  const size_t i = pixelOf(toUv(dir));
  const Rgb c = image_->pixels()[i] * strength_;
  return isFinite(c) ? glm::max(c, Rgb(0.0f)) : Rgb(0.0f);
}

Environment::Sample Environment::sample(Vec2 u) const {
  Sample s;
  if (!image_) {  // uniform over the sphere
    const float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
    s.dir = Vec3(r * std::cos(phi), z, r * std::sin(phi));
    s.radiance = color_;
    s.pdf = 1.0f / (4.0f * kPi);
    return s;
  }
  const auto w = static_cast<size_t>(image_->width()), h = static_cast<size_t>(image_->height());
  const size_t y = findInterval(rowCdf_.data(), h, u.y);
  const float rowLow = rowCdf_[y], rowHigh = rowCdf_[y + 1];
  const float dv = rowHigh > rowLow ? (u.y - rowLow) / (rowHigh - rowLow) : 0.5f;
  const float* cdf = &columnCdf_[y * (w + 1)];
  const size_t x = findInterval(cdf, w, u.x);
  const float du = cdf[x + 1] > cdf[x] ? (u.x - cdf[x]) / (cdf[x + 1] - cdf[x]) : 0.5f;
  const Vec2 uv((static_cast<float>(x) + std::clamp(du, 0.0f, 0.999f)) / static_cast<float>(w),
                (static_cast<float>(y) + std::clamp(dv, 0.001f, 0.999f)) / static_cast<float>(h));
  s.dir = glm::normalize(fromUv(uv));
  s.radiance = radiance(s.dir);
  s.pdf = pdf(s.dir);
  return s;
}

float Environment::pdf(const Vec3& dir) const {
  if (!image_) return 1.0f / (4.0f * kPi);
  const Vec2 uv = toUv(dir);
  const float sinTheta = std::sin(uv.y * kPi);
  if (!(sinTheta > 0.0f) || !(weightSum_ > 0.0)) return 0.0f;
  const double pixels = static_cast<double>(weight_.size());
  // density over the unit square of (u, v), then over the sphere: d omega = 2 pi^2 sin(theta) du dv
  const double pdfUv = static_cast<double>(weight_[pixelOf(uv)]) * pixels / weightSum_;
  return static_cast<float>(pdfUv / (2.0 * kPiD * kPiD * static_cast<double>(sinTheta)));
}

}  // namespace ll
