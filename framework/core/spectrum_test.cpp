#include "core/spectrum.h"

#include <filesystem>
#include <fstream>

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

}  // namespace
}  // namespace ll
