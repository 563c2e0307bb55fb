#include "core/image.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"

namespace ll {
namespace {

namespace fs = std::filesystem;

// A fresh file name in gtest's temporary folder, unique per test.
std::string tempPath(const std::string& name) {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  // A folder of this process's own (test binaries may run concurrently, e.g.
  // ctest -j), removed when the process exits.
  struct Folder {
    fs::path path = fs::path(testing::TempDir()) / ("lightlab_image_test_" + std::to_string(std::random_device{}()));
    ~Folder() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  const fs::path& dir = folder.path;
  fs::create_directories(dir);
  const fs::path p = dir / (std::string(info->name()) + "_" + name);
  fs::remove(p);
  return p.string();
}

// A non-square image with distinct values per pixel and channel, so that
// transposed, flipped or channel-swapped files are caught.
Image gradientImage(int w, int h, float scale) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float fx = static_cast<float>(x) / static_cast<float>(w - 1);
      const float fy = static_cast<float>(y) / static_cast<float>(h - 1);
      img.at(x, y) = scale * Rgb(fx, fy, 0.25f + 0.5f * fx * fy);
    }
  return img;
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Writes `img` to `path` and reads it back.
Image saveAndLoad(const Image& img, const std::string& path) {
  saveImage(img, path);
  return loadImage(path);
}

TEST(Image, ConstructionFillAndMean) {
  Image img(3, 2, Rgb(0.5f, 1.0f, 2.0f));
  EXPECT_EQ(img.width(), 3);
  EXPECT_EQ(img.height(), 2);
  EXPECT_EQ(img.pixelCount(), 6u);
  EXPECT_FALSE(img.empty());
  img.at(2, 1) = Rgb(6.5f, 1.0f, -4.0f);  // row-major: the last pixel
  EXPECT_EQ(img.pixels().back(), Rgb(6.5f, 1.0f, -4.0f));
  const Rgb m = img.mean();
  EXPECT_FLOAT_EQ(m.r, (5.0f * 0.5f + 6.5f) / 6.0f);
  EXPECT_FLOAT_EQ(m.g, 1.0f);
  EXPECT_FLOAT_EQ(m.b, (5.0f * 2.0f - 4.0f) / 6.0f);
  EXPECT_TRUE(Image().empty());
  EXPECT_EQ(Image().mean(), Rgb(0.0f));
}

TEST(Image, SrgbKnownPoints) {
  EXPECT_EQ(linearToSrgb(0.0f), 0.0f);
  EXPECT_NEAR(linearToSrgb(1.0f), 1.0f, 1e-6f);
  EXPECT_EQ(srgbToLinear(0.0f), 0.0f);
  EXPECT_NEAR(srgbToLinear(1.0f), 1.0f, 1e-6f);
  // 1.055 * 0.5^(1/2.4) - 0.055 = 0.735357
  EXPECT_NEAR(linearToSrgb(0.5f), 0.7353569f, 1e-6f);
  EXPECT_NEAR(srgbToLinear(0.7353569f), 0.5f, 1e-6f);
  // 18 % grey encodes to about 0.4614 (the "middle grey" of sRGB).
  EXPECT_NEAR(linearToSrgb(0.18f), 0.4613561f, 1e-6f);
  // Linear segment: slope 12.92 below 0.0031308.
  EXPECT_NEAR(linearToSrgb(0.001f), 0.01292f, 1e-7f);
  EXPECT_NEAR(srgbToLinear(0.01292f), 0.001f, 1e-8f);
  // Out-of-range input is clamped when encoding.
  EXPECT_EQ(linearToSrgb(-0.5f), 0.0f);
  EXPECT_NEAR(linearToSrgb(7.0f), 1.0f, 1e-6f);
}

TEST(Image, SrgbBoundaryIsContinuous) {
  // At the breakpoint 0.0031308 both branches give 0.04045 (to 1e-6), and the
  // decoder's breakpoint 0.04045 maps back to 0.0031308.
  const float kLin = 0.0031308f;
  const float linearBranch = 12.92f * kLin;
  const float powerBranch = 1.055f * std::pow(kLin, 1.0f / 2.4f) - 0.055f;
  EXPECT_NEAR(linearBranch, powerBranch, 1e-6f);
  EXPECT_NEAR(linearToSrgb(kLin), 0.04045f, 1e-6f);
  EXPECT_NEAR(linearToSrgb(std::nextafter(kLin, 1.0f)), 0.04045f, 1e-6f);
  EXPECT_NEAR(linearToSrgb(std::nextafter(kLin, 0.0f)), 0.04045f, 1e-6f);
  EXPECT_NEAR(srgbToLinear(0.04045f), kLin, 1e-7f);
  EXPECT_NEAR(srgbToLinear(std::nextafter(0.04045f, 1.0f)), kLin, 1e-7f);
}

TEST(Image, SrgbEncodeDecodeAreInverse) {
  float previous = -1.0f;
  for (int i = 0; i <= 10000; ++i) {
    const float x = static_cast<float>(i) / 10000.0f;
    ASSERT_NEAR(srgbToLinear(linearToSrgb(x)), x, 1e-6f) << x;
    ASSERT_NEAR(linearToSrgb(srgbToLinear(x)), x, 1e-6f) << x;
    const float e = linearToSrgb(x);
    ASSERT_GT(e, previous) << "encoding must be strictly increasing at " << x;
    previous = e;
  }
}

TEST(Image, PfmRoundTripIsBitExact) {
  Image img = gradientImage(7, 5, 3.0f);
  // Values 8-bit formats cannot hold: negatives, huge, tiny and denormals.
  img.at(0, 0) = Rgb(-1.5f, 1e30f, 1e-30f);
  img.at(6, 4) = Rgb(std::numeric_limits<float>::denorm_min(), 65504.0f, 0.1f);
  img.at(3, 2) = Rgb(std::numeric_limits<float>::max(), -0.0f, 1.0f / 3.0f);
  const std::string path = tempPath("exact.pfm");
  const Image back = saveAndLoad(img, path);
  ASSERT_EQ(back.width(), 7);
  ASSERT_EQ(back.height(), 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x)
      for (int c = 0; c < 3; ++c) {
        const float a = img.at(x, y)[c], b = back.at(x, y)[c];
        ASSERT_EQ(std::memcmp(&a, &b, sizeof(float)), 0) << x << "," << y << " channel " << c;
      }
}

TEST(Image, PfmFileLayoutIsLittleEndianBottomUp) {
  Image img(2, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 2; ++x) img.at(x, y) = Rgb(static_cast<float>(10 * y + x), 0.5f, -2.0f);
  const std::string path = tempPath("layout.pfm");
  saveImage(img, path);
  const std::string bytes = readBytes(path);
  const std::string header = "PF\n2 3\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 2u * 3u * 3u * sizeof(float));
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  // The first stored row is the bottom one (y = 2): red = 20, 21.
  float first[3];
  std::memcpy(first, bytes.data() + header.size(), sizeof(first));
  EXPECT_EQ(first[0], 20.0f);
  EXPECT_EQ(first[1], 0.5f);
  EXPECT_EQ(first[2], -2.0f);
  float last;
  std::memcpy(&last, bytes.data() + bytes.size() - 3 * sizeof(float), sizeof(float));
  EXPECT_EQ(last, 1.0f);  // top row, x = 1
}

TEST(Image, PfmGreyscaleLoadsAsGrey) {
  const std::string path = tempPath("grey.pfm");
  {
    std::ofstream out(path, std::ios::binary);
    out << "Pf\n3 1\n-1.0\n";
    const float v[3] = {0.25f, 2.0f, -1.0f};
    out.write(reinterpret_cast<const char*>(v), sizeof(v));
  }
  const Image img = loadImage(path);
  ASSERT_EQ(img.width(), 3);
  ASSERT_EQ(img.height(), 1);
  EXPECT_EQ(img.at(0, 0), Rgb(0.25f));
  EXPECT_EQ(img.at(1, 0), Rgb(2.0f));
  EXPECT_EQ(img.at(2, 0), Rgb(-1.0f));
}

TEST(Image, PfmRejectsBadFiles) {
  const std::string bigEndian = tempPath("big.pfm");
  {
    std::ofstream out(bigEndian, std::ios::binary);
    out << "PF\n1 1\n1.0\n";
    const float v[3] = {1.0f, 1.0f, 1.0f};
    out.write(reinterpret_cast<const char*>(v), sizeof(v));
  }
  const std::string truncated = tempPath("truncated.pfm");
  {
    std::ofstream out(truncated, std::ios::binary);
    out << "PF\n4 4\n-1.0\n";
    const float v[3] = {1.0f, 1.0f, 1.0f};
    out.write(reinterpret_cast<const char*>(v), sizeof(v));
  }
  const std::string notPfm = tempPath("text.pfm");
  { std::ofstream(notPfm) << "P6\n1 1\n255\n"; }
  for (const std::string& path : {bigEndian, truncated, notPfm}) {
    try {
      loadImage(path);
      ADD_FAILURE() << "expected UserError for " << path;
    } catch (const UserError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    }
  }
}

TEST(Image, HdrRoundTripWithinRgbePrecision) {
  Image img = gradientImage(9, 4, 40.0f);
  img.at(1, 1) = Rgb(1000.0f, 0.001f, 3.0f);
  const std::string path = tempPath("round.hdr");
  const Image back = saveAndLoad(img, path);
  ASSERT_EQ(back.width(), 9);
  ASSERT_EQ(back.height(), 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 9; ++x) {
      // RGBE: 8-bit mantissas sharing the exponent of the largest channel, so
      // each channel is within one step of max/128 (truncating encoder).
      const Rgb a = img.at(x, y), b = back.at(x, y);
      const float step = maxComponent(a) / 128.0f;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(b[c], a[c], step + 1e-12f) << x << "," << y << " c" << c;
    }
}

TEST(Image, PngRoundTripWithinQuantisation) {
  const Image img = gradientImage(11, 6, 1.0f);
  const std::string path = tempPath("round.png");
  const Image back = saveAndLoad(img, path);
  ASSERT_EQ(back.width(), 11);
  ASSERT_EQ(back.height(), 6);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 11; ++x)
      for (int c = 0; c < 3; ++c) {
        // 8-bit sRGB: half a code value in encoded space.
        const float a = linearToSrgb(img.at(x, y)[c]), b = linearToSrgb(back.at(x, y)[c]);
        ASSERT_NEAR(a, b, 0.5f / 255.0f + 1e-5f) << x << "," << y << " c" << c;
      }
}

TEST(Image, PngClampsAndAppliesExposure) {
  Image img(3, 1);
  img.at(0, 0) = Rgb(0.25f);
  img.at(1, 0) = Rgb(5.0f);   // above white
  img.at(2, 0) = Rgb(-1.0f);  // below black
  const std::string path = tempPath("exposure.png");
  saveImage(img, path, ToneMap{1.0f});  // one stop: x2
  const Image back = loadImage(path);
  EXPECT_NEAR(linearToSrgb(back.at(0, 0).g), linearToSrgb(0.5f), 0.5f / 255.0f + 1e-5f);
  EXPECT_EQ(back.at(1, 0), Rgb(1.0f));
  EXPECT_EQ(back.at(2, 0), Rgb(0.0f));
}

TEST(Image, UnknownExtensionListsAllowed) {
  const Image img(2, 2, Rgb(0.5f));
  const std::string path = tempPath("picture.bmp");
  try {
    saveImage(img, path);
    FAIL() << "expected UserError";
  } catch (const UserError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;
    EXPECT_NE(msg.find("'.bmp'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(allowed: .png, .jpg, .hdr, .pfm)"), std::string::npos) << msg;
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_THROW(saveImage(img, tempPath("noextension")), UserError);
}

TEST(Image, ExtensionIsCaseInsensitive) {
  const Image img = gradientImage(3, 2, 2.0f);
  const std::string path = tempPath("upper.PFM");
  saveImage(img, path);
  EXPECT_EQ(loadImage(path).pixels(), img.pixels());
}

TEST(Image, SavingEmptyImageThrows) {
  EXPECT_THROW(saveImage(Image(), tempPath("empty.png")), UserError);
  EXPECT_THROW(saveImage(Image(), tempPath("empty.pfm")), UserError);
}

TEST(Image, WritingMakesMissingFoldersAndAnImpossibleOneThrowsNamingPath) {
  const fs::path base = fs::path(testing::TempDir()) / "no_such_dir_ll";
  fs::remove_all(base);
  saveImage(Image(2, 2), (base / "x" / "out.png").string());  // `-o out/a2.png` in a fresh checkout
  EXPECT_TRUE(fs::exists(base / "x" / "out.png"));
  const std::string path = (base / "x" / "out.png" / "below_a_file.png").string();
  try {
    saveImage(Image(2, 2), path);
    FAIL() << "expected UserError";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  fs::remove_all(base);
}

TEST(Image, LoadingMissingFileNamesPath) {
  const std::string path = tempPath("does_not_exist.png");
  try {
    loadImage(path);
    FAIL() << "expected UserError";
  } catch (const UserError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find("no such image file"), std::string::npos) << msg;
  }
}

TEST(Image, LoadingGarbageNamesPathAndFormats) {
  const std::string path = tempPath("garbage.png");
  { std::ofstream(path) << "this is not a png"; }
  try {
    loadImage(path);
    FAIL() << "expected UserError";
  } catch (const UserError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find(".pfm"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace ll

namespace ll {
namespace {

TEST(Srgb8, TableEncoderMatchesTheFormulaEverywhere) {
  // Dense sweep over [0, 1] plus out-of-range and non-finite inputs.
  int mismatches = 0;
  for (int i = 0; i <= 1000000; ++i) {
    const float v = static_cast<float>(i) / 1000000.0f;
    const float scaled = 255.0f * linearToSrgb(v);
    const bool nearTie = std::abs(scaled - std::floor(scaled) - 0.5f) < 1e-3f;  // may round either way
    if (linearToSrgb8(v) != std::lround(scaled) && !nearTie) ++mismatches;
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(linearToSrgb8(-1.0f), 0);
  EXPECT_EQ(linearToSrgb8(2.0f), 255);
  EXPECT_EQ(linearToSrgb8(std::numeric_limits<float>::infinity()), 255);
  EXPECT_EQ(linearToSrgb8(std::nanf("")), 0);
}

}  // namespace
}  // namespace ll
