#include "core/image.h"

#include "core/files.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

#include <stb_image.h>
#include <stb_image_write.h>

#include "core/error.h"

namespace ll {

Image::Image(int width, int height, Rgb fill)
    : width_(width), height_(height), pixels_(static_cast<size_t>(width) * height, fill) {}

Rgb Image::mean() const {
  glm::dvec3 sum(0.0);
  for (const Rgb& p : pixels_) sum += glm::dvec3(p);
  return pixels_.empty() ? Rgb(0.0f) : Rgb(sum / static_cast<double>(pixels_.size()));
}

float linearToSrgb(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

uint8_t linearToSrgb8(float v) {
  // thresholds[k]: the smallest linear value whose code is k + 1 (the inverse at code k + 0.5).
  static const std::array<float, 255> thresholds = [] {
    std::array<float, 255> t{};
    for (int k = 0; k < 255; ++k) t[static_cast<size_t>(k)] = srgbToLinear((static_cast<float>(k) + 0.5f) / 255.0f);
    return t;
  }();
  if (!(v > 0.0f)) return 0;  // also NaN
  return static_cast<uint8_t>(std::upper_bound(thresholds.begin(), thresholds.end(), v) - thresholds.begin());
}

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void savePfm(const Image& image, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throwUserError(path + ": cannot open for writing");
  // PF = colour; a negative scale means little-endian; rows go bottom to top.
  out << "PF\n" << image.width() << " " << image.height() << "\n-1.0\n";
  for (int y = image.height() - 1; y >= 0; --y)
    out.write(reinterpret_cast<const char*>(&image.at(0, y)),
              static_cast<std::streamsize>(sizeof(Rgb)) * image.width());
  if (!out) throwUserError(path + ": write failed");
}

Image loadPfm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throwUserError(path + ": cannot open");
  std::string magic;
  int w = 0, h = 0;
  float scale = 0.0f;
  in >> magic >> w >> h >> scale;
  in.get();  // the single whitespace byte after the header
  if (!in || (magic != "PF" && magic != "Pf") || w <= 0 || h <= 0 || w > 65536 || h > 65536)
    throwUserError(path + ": not a PFM file (expected 'PF' or 'Pf', width, height, scale)");
  if (scale > 0.0f) throwUserError(path + ": big-endian PFM is not supported");
  const int channels = magic == "PF" ? 3 : 1;
  Image image(w, h);
  std::vector<float> row(static_cast<size_t>(w) * channels);
  for (int y = h - 1; y >= 0; --y) {
    in.read(reinterpret_cast<char*>(row.data()), static_cast<std::streamsize>(row.size() * 4));
    if (!in) throwUserError(path + ": truncated PFM data");
    for (int x = 0; x < w; ++x)
      image.at(x, y) = channels == 3 ? Rgb(row[3 * x], row[3 * x + 1], row[3 * x + 2]) : Rgb(row[x]);
  }
  return image;
}

}  // namespace

void saveImage(const Image& image, const std::string& path, ToneMap tone) {
  createParentDirectory(path);
  const std::string ext = lowerExtension(path);
  if (image.empty()) throwUserError(path + ": refusing to write an empty image");
  const int w = image.width(), h = image.height();
  if (ext == ".pfm") return savePfm(image, path);
  if (ext == ".hdr") {
    if (!stbi_write_hdr(path.c_str(), w, h, 3, &image.pixels()[0].x))
      throwUserError(path + ": cannot write HDR file");
    return;
  }
  if (ext != ".png" && ext != ".jpg" && ext != ".jpeg")
    throwUserError(path + ": unknown image extension '" + ext + "' (allowed: .png, .jpg, .hdr, .pfm)");
  const float scale = std::exp2(tone.exposure);
  std::vector<unsigned char> bytes(static_cast<size_t>(w) * h * 3);
  for (size_t i = 0; i < image.pixelCount(); ++i)
    for (int c = 0; c < 3; ++c)
      bytes[3 * i + c] =
          linearToSrgb8(scale * image.pixels()[i][c]);
  const int ok = ext == ".png" ? stbi_write_png(path.c_str(), w, h, 3, bytes.data(), 3 * w)
                               : stbi_write_jpg(path.c_str(), w, h, 3, bytes.data(), 95);
  if (!ok) throwUserError(path + ": cannot write image (does the folder exist?)");
}

Image loadImage(const std::string& path) {
  checkInputFile(path, "image file", kMaxImageFileBytes);
  const std::string ext = lowerExtension(path);
  if (ext == ".pfm") return loadPfm(path);
  int w = 0, h = 0, n = 0;
  if (ext == ".hdr") {
    std::unique_ptr<float, void (*)(void*)> data(stbi_loadf(path.c_str(), &w, &h, &n, 3), stbi_image_free);
    if (!data) throwUserError(path + ": cannot read HDR image: " + stbi_failure_reason());
    Image image(w, h);
    std::memcpy(image.pixels().data(), data.get(), sizeof(float) * 3 * static_cast<size_t>(w) * h);
    return image;
  }
  std::unique_ptr<unsigned char, void (*)(void*)> data(stbi_load(path.c_str(), &w, &h, &n, 3),
                                                       stbi_image_free);
  if (!data)
    throwUserError(path + ": cannot read image (" + stbi_failure_reason() +
                   "; allowed: .png, .jpg, .bmp, .tga, .hdr, .pfm)");
  Image image(w, h);
  for (size_t i = 0; i < image.pixelCount(); ++i)
    for (int c = 0; c < 3; ++c) image.pixels()[i][c] = srgbToLinear(data.get()[3 * i + c] / 255.0f);
  return image;
}

}  // namespace ll
