#include "core/spectrum.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/error.h"

namespace ll {
namespace {

const std::string kSpectra = std::string(LIGHTLAB_DATA_DIR) + "/spectra/";

Rgb metalF0(const std::string& file) {
  const SpectrumTable t = loadSpectraCsv(kSpectra + file);
  EXPECT_EQ(t.names, (std::vector<std::string>{"n", "k"}));
  return metalNormalReflectance(t.columns[0], t.columns[1]);
}

void expectNear(const Rgb& got, const Rgb& want, float tolerance) {
  EXPECT_NEAR(got.r, want.r, tolerance);
  EXPECT_NEAR(got.g, want.g, tolerance);
  EXPECT_NEAR(got.b, want.b, tolerance);
}

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(Spectrum, InterpolatesLinearlyAndClampsAtTheEnds) {
  const Spectrum s{{400.0f, 500.0f, 600.0f}, {1.0f, 3.0f, 2.0f}};
  EXPECT_FLOAT_EQ(s.at(450.0f), 2.0f);
  EXPECT_FLOAT_EQ(s.at(575.0f), 2.25f);
  EXPECT_FLOAT_EQ(s.at(500.0f), 3.0f);
  EXPECT_FLOAT_EQ(s.at(300.0f), 1.0f);
  EXPECT_FLOAT_EQ(s.at(900.0f), 2.0f);
}

// The CIE 1931 ȳ table sums to 106.857 over 360-830 nm at 1 nm steps.
TEST(Spectrum, CieYIntegral) {
  double sum = 0.0;
  for (int nm = 360; nm <= 830; ++nm) sum += static_cast<double>(cieY(static_cast<float>(nm)));
  EXPECT_NEAR(sum, 106.86, 0.01 * 106.86);
  EXPECT_NEAR(cieY(555.0f), 1.0, 0.03);  // the photopic peak
}

TEST(Spectrum, ConstantOneIsWhite) {
  expectNear(reflectanceToRgb(Spectrum{{500.0f}, {1.0f}}), Rgb(1.0f), 1e-5f);
  expectNear(reflectanceToRgb(Spectrum{{380.0f, 780.0f}, {0.5f, 0.5f}}), Rgb(0.5f), 1e-5f);
}

// Linear sRGB F0 of the measured metals against the commonly quoted linear
// values (e.g. Real-Time Rendering, 4th ed., Table 9.2), within 0.06.
TEST(Spectrum, MetalNormalReflectance) {
  const Rgb cu = metalF0("metal_cu.csv");
  expectNear(cu, {0.955f, 0.638f, 0.538f}, 0.06f);
  EXPECT_GT(cu.r, cu.g);
  EXPECT_GT(cu.g, cu.b);
  expectNear(metalF0("metal_au.csv"), {1.0f, 0.766f, 0.336f}, 0.06f);
  expectNear(metalF0("metal_al.csv"), {0.913f, 0.922f, 0.924f}, 0.06f);
  expectNear(metalF0("metal_ag.csv"), {0.972f, 0.960f, 0.915f}, 0.06f);
}

TEST(Spectrum, CornellBoxTables) {
  const SpectrumTable box = loadSpectraCsv(kSpectra + "cornell_box.csv");
  EXPECT_EQ(box.names, (std::vector<std::string>{"white", "red", "green"}));
  EXPECT_EQ(box.columns[0].nm.size(), 76u);  // 400-700 nm, 4 nm apart
  const Rgb red = reflectanceToRgb(box.columns[1]), green = reflectanceToRgb(box.columns[2]);
  EXPECT_GT(red.r, 4.0f * red.g);
  EXPECT_GT(green.g, 2.0f * green.r);
  const SpectrumTable light = loadSpectraCsv(kSpectra + "cornell_box_light.csv");
  EXPECT_EQ(light.names, (std::vector<std::string>{"emission"}));
  EXPECT_FLOAT_EQ(light.columns[0].at(650.0f), 17.0f);
}

TEST(Spectrum, DecreasingWavelengthNamesFileAndLine) {
  const std::string path = writeTemp("lightlab_spectrum_decreasing.csv",
                                     "wavelength_nm,n,k\n400,1,2\n500,1,2\n450,1,2\n");
  try {
    loadSpectraCsv(path);
    FAIL() << "no error";
  } catch (const UserError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path + ":4:"), std::string::npos) << message;
    EXPECT_NE(message.find("increas"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(Spectrum, BadTablesAreOneLineErrors) {
  const auto errorOf = [](const std::string& name, const std::string& text) {
    const std::string path = writeTemp(name, text);
    try {
      loadSpectraCsv(path);
    } catch (const UserError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(errorOf("lightlab_spectrum_nan.csv", "wavelength_nm,n\n400,abc\n").find(":2:5: 'abc'"),
            std::string::npos);
  EXPECT_NE(
      errorOf("lightlab_spectrum_cols.csv", "wavelength_nm,n,k\n400,1\n").find(":2: 2 values"),
      std::string::npos);
  EXPECT_NE(errorOf("lightlab_spectrum_head.csv", "nm,n\n400,1\n").find(":1:1: the header"),
            std::string::npos);
  EXPECT_NE(
      errorOf("lightlab_spectrum_empty.csv", "wavelength_nm,n\r\n\r\n").find(":1: no data rows"),
      std::string::npos);
  try {
    loadSpectraCsv(kSpectra + "no_such_table.csv");
    ADD_FAILURE() << "no error";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_table.csv: no such spectrum table"),
              std::string::npos);
  }
}

const RgbToSpectrum& smits() { return defaultRgbToSpectrum(std::string(LIGHTLAB_DATA_DIR) + "/spectra"); }

// eval sampled at 1 nm over 360-830 nm: exactly the samples reflectanceToRgb integrates.
Spectrum sampled(const RgbToSpectrum& t, const Rgb& rgb) {
  Spectrum s;
  for (int nm = 360; nm <= 830; ++nm) {
    s.nm.push_back(static_cast<float>(nm));
    s.value.push_back(t.eval(rgb, static_cast<float>(nm)));
  }
  return s;
}

// P[eval(rgb)]: the RGB the spectrum projects back to.
Rgb roundTrip(const RgbToSpectrum& t, const Rgb& rgb) { return reflectanceToRgb(sampled(t, rgb)); }

// The tables' white is flat at about 1.062, so P[eval(rgb)] ≈ kSmitsGain rgb
// (spectrum.h); measured 1.0618-1.0627 per channel for a grey.
constexpr float kSmitsGain = 1.062f;

// Cornell box white, red, green; a blue; a yellow.
const std::vector<Rgb> kColours = {{0.725f, 0.71f, 0.68f}, {0.63f, 0.065f, 0.05f},
                                   {0.14f, 0.45f, 0.091f}, {0.1f, 0.2f, 0.8f},
                                   {0.8f, 0.7f, 0.1f}};

// Largest |P[eval(c)] - c| and |P[eval(c)] - kSmitsGain c| over the channels of kColours.
struct RoundTripErrors {
  float raw = 0.0f, gainCorrected = 0.0f;
};
RoundTripErrors roundTripErrors(const RgbToSpectrum& t, bool print) {
  RoundTripErrors e;
  for (const Rgb& c : kColours) {
    const Rgb p = roundTrip(t, c);
    const Rgb raw = p - c, corrected = p - kSmitsGain * c;
    if (print)
      std::printf(
          "  (%.3f, %.3f, %.3f) -> (%.4f, %.4f, %.4f): error %+.4f %+.4f %+.4f, after /%.3f "
          "%+.4f %+.4f %+.4f\n",
          double(c.r), double(c.g), double(c.b), double(p.r), double(p.g), double(p.b),
          double(raw.r), double(raw.g), double(raw.b), double(kSmitsGain),
          double(p.r / kSmitsGain - c.r), double(p.g / kSmitsGain - c.g),
          double(p.b / kSmitsGain - c.b));
    for (int i = 0; i < 3; ++i) {
      e.raw = std::max(e.raw, std::abs(raw[i]));
      e.gainCorrected = std::max(e.gainCorrected, std::abs(corrected[i]));
    }
  }
  return e;
}

TEST(Spectrum, RgbToSpectrumReadsPbrtTables) {
  const RgbToSpectrum& t = smits();
  // Spot values of pbrt-v3's RGBRefl2Spect* arrays at the first and last rows.
  EXPECT_FLOAT_EQ(t.eval({1.0f, 1.0f, 1.0f}, 380.0f), 1.0618958571272863f);
  EXPECT_FLOAT_EQ(t.eval({0.0f, 0.0f, 1.0f}, 380.0f), 0.99209771469720676f);
  EXPECT_FLOAT_EQ(t.eval({1.0f, 0.0f, 0.0f}, 720.0f), 0.98713907792319400f);
  EXPECT_FLOAT_EQ(t.eval({0.0f, 1.0f, 1.0f}, 720.0f), 2.5259399415550079e-02f);  // cyan
  // Clamped to the end rows outside 380-720 nm, linear between rows.
  const Rgb c(0.3f, 0.6f, 0.2f);
  EXPECT_FLOAT_EQ(t.eval(c, 300.0f), t.eval(c, 380.0f));
  EXPECT_FLOAT_EQ(t.eval(c, 830.0f), t.eval(c, 720.0f));
  const float a = t.eval(c, 500.645172f), b = t.eval(c, 511.612915f);
  EXPECT_NEAR(t.eval(c, 0.5f * (500.645172f + 511.612915f)), 0.5f * (a + b), 1e-5f);
  // Negative components count as 0.
  EXPECT_FLOAT_EQ(t.eval({-0.5f, 0.3f, 0.2f}, 550.0f), t.eval({0.0f, 0.3f, 0.2f}, 550.0f));
  EXPECT_EQ(t.eval({-1.0f, -2.0f, -3.0f}, 550.0f), 0.0f);
  EXPECT_EQ(&t, &smits());  // loaded once
}

TEST(Spectrum, RgbToSpectrumGreyRoundTrip) {
  const Rgb grey = roundTrip(smits(), Rgb(0.5f));
  std::printf("  P[eval(0.5, 0.5, 0.5)] = (%.5f, %.5f, %.5f)\n", double(grey.r), double(grey.g),
              double(grey.b));
  EXPECT_NEAR(grey.r, grey.g, 1e-3f);
  EXPECT_NEAR(grey.g, grey.b, 1e-3f);
  EXPECT_NEAR(grey.r, grey.b, 1e-3f);
  expectNear(grey, Rgb(0.5f * kSmitsGain), 1e-3f);  // measured 0.5309-0.5314
  expectNear(grey, Rgb(0.5f), 0.035f);
}

// Smits is approximate. Measured: largest |P[eval(c)] - c| 0.0456 (the blue's
// blue, mostly the 1.062 gain), largest |P[eval(c)] - 1.062 c| 0.021 (the
// Cornell red's red). Tolerances 0.05 and 0.025. Swapping the red and blue
// tables gives errors near 0.6 (RgbToSpectrumRoundTripCatchesSwappedTables).
TEST(Spectrum, RgbToSpectrumRoundTrip) {
  const RoundTripErrors e = roundTripErrors(smits(), true);
  std::printf("  largest error %.4f, %.4f after the gain\n", double(e.raw), double(e.gainCorrected));
  EXPECT_LT(e.raw, 0.05f);
  EXPECT_LT(e.gainCorrected, 0.025f);
  // Each colour keeps its hue: the largest channel stays the largest.
  for (const Rgb& c : kColours) {
    const Rgb p = roundTrip(smits(), c);
    const int want = c.r >= c.g && c.r >= c.b ? 0 : (c.g >= c.b ? 1 : 2);
    const int got = p.r >= p.g && p.r >= p.b ? 0 : (p.g >= p.b ? 1 : 2);
    EXPECT_EQ(got, want) << c.r << " " << c.g << " " << c.b;
  }
}

TEST(Spectrum, RgbToSpectrumRoundTripCatchesSwappedTables) {
  std::ifstream in(kSpectra + "smits_rgb_to_spectrum.csv");
  std::stringstream text;
  text << in.rdbuf();
  std::string csv = text.str();
  const std::string header = "wavelength_nm,white,cyan,magenta,yellow,red,green,blue";
  ASSERT_EQ(csv.rfind(header, 0), 0u);
  csv.replace(0, header.size(), "wavelength_nm,white,cyan,magenta,yellow,blue,green,red");
  const RgbToSpectrum swapped(writeTemp("lightlab_smits_swapped.csv", csv));
  const RoundTripErrors e = roundTripErrors(swapped, false);
  std::printf("  red and blue swapped: largest error %.4f\n", double(e.raw));
  EXPECT_GT(e.raw, 0.05f);
  EXPECT_GT(e.gainCorrected, 0.025f);
}

// Emission: eval(k rgb) = k eval(rgb), so P[eval(10 rgb)] = 10 P[eval(rgb)].
TEST(Spectrum, RgbToSpectrumIsLinearForEmission) {
  const RgbToSpectrum& t = smits();
  std::vector<Rgb> colours = kColours;
  colours.push_back(Rgb(1.0f));
  colours.push_back({17.0f, 12.0f, 4.0f});  // a light, already above 1
  for (const Rgb& c : colours) {
    for (int nm = 360; nm <= 830; ++nm) {
      const float l = static_cast<float>(nm), one = t.eval(c, l);
      EXPECT_NEAR(t.eval(10.0f * c, l), 10.0f * one, 1e-5f * std::max(1.0f, 10.0f * one));
    }
    expectNear(roundTrip(t, 10.0f * c), 10.0f * roundTrip(t, c), 1e-4f * (10.0f * c.r + 1.0f));
  }
}

// Over a grid of reflectances in [0,1]³ (step 0.1) and 360-830 nm: never
// negative, and at most the tables' largest value, 1.0626 (white at 610 nm);
// measured max 1.0626 for (1,1,1).
TEST(Spectrum, RgbToSpectrumBoundsForReflectances) {
  const RgbToSpectrum& t = smits();
  float lo = 1.0f, hi = 0.0f;
  Rgb argmax(0.0f);
  for (int r = 0; r <= 10; ++r)
    for (int g = 0; g <= 10; ++g)
      for (int b = 0; b <= 10; ++b) {
        const Rgb c = 0.1f * Rgb(static_cast<float>(r), static_cast<float>(g), static_cast<float>(b));
        for (int nm = 360; nm <= 830; ++nm) {
          const float v = t.eval(c, static_cast<float>(nm));
          lo = std::min(lo, v);
          if (v > hi) hi = v, argmax = c;
        }
      }
  std::printf("  reflectances: min %.5f, max %.5f at (%.1f, %.1f, %.1f)\n", double(lo), double(hi),
              double(argmax.r), double(argmax.g), double(argmax.b));
  EXPECT_GE(lo, 0.0f);
  EXPECT_LE(hi, 1.065f);
}

TEST(Spectrum, RgbToSpectrumMissingColumnsAreNamed) {
  const auto errorOf = [](const std::string& name, const std::string& text) {
    try {
      RgbToSpectrum t(writeTemp(name, text));
    } catch (const UserError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string path = (std::filesystem::temp_directory_path() / "lightlab_smits_cols.csv").string();
  const std::string message = errorOf("lightlab_smits_cols.csv",
                                      "# comment\nwavelength_nm,white,cyan,magenta,yellow,red\n400,1,1,1,1,1\n");
  EXPECT_NE(message.find(path + ":2: "), std::string::npos) << message;
  EXPECT_NE(message.find("missing: green, blue"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_NE(errorOf("lightlab_smits_nan.csv", "wavelength_nm,white\n400,x\n").find(":2:5: 'x'"),
            std::string::npos);
  try {
    RgbToSpectrum t(kSpectra + "no_such_table.csv");
    ADD_FAILURE() << "no error";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_table.csv: no such spectrum table"),
              std::string::npos)
        << e.what();
  }
}

// Run alone (--gtest_filter) this races the first, loading call.
TEST(Spectrum, DefaultRgbToSpectrumIsSharedAcrossThreads) {
  std::vector<const RgbToSpectrum*> seen(8, nullptr);
  std::vector<std::thread> threads;
  for (size_t i = 0; i < seen.size(); ++i) threads.emplace_back([&seen, i] { seen[i] = &smits(); });
  for (std::thread& th : threads) th.join();
  for (const RgbToSpectrum* p : seen) EXPECT_EQ(p, seen[0]);
}

}  // namespace
}  // namespace ll
