#include "core/params.h"

#include <string>

#include <gtest/gtest.h>

#include "test_support.h"
#include <nlohmann/json.hpp>

#include "core/error.h"

namespace ll {
namespace {

ParamSet makeParams() {
  return ParamSet("technique 'demo'",
                  {
                      ParamDecl::integer("samples", 16, 1, 256, "samples per pixel"),
                      ParamDecl::real("alpha", 0.25, 0.0, 1.5, "blend factor"),
                      ParamDecl::boolean("shadows", true, "cast shadow rays"),
                      ParamDecl::choice("mode", "fast", {"fast", "exact", "debug"}, "quality"),
                  });
}

using testing_support::contains;
using testing_support::errorOf;

TEST(Params, DeclarationsDescribeThemselves) {
  const ParamSet p = makeParams();
  ASSERT_EQ(p.decls().size(), 4u);
  EXPECT_EQ(p.owner(), "technique 'demo'");
  EXPECT_EQ(p.decls()[0].typeName(), "int");
  EXPECT_EQ(p.decls()[1].typeName(), "float");
  EXPECT_EQ(p.decls()[2].typeName(), "bool");
  EXPECT_EQ(p.decls()[3].typeName(), "choice");
  EXPECT_EQ(p.decls()[0].rangeText(), "[1, 256]");
  EXPECT_EQ(p.decls()[1].rangeText(), "[0, 1.5]");
  EXPECT_EQ(p.decls()[2].rangeText(), "true or false");
  EXPECT_EQ(p.decls()[3].rangeText(), "one of: fast, exact, debug");
  EXPECT_EQ(p.decls()[0].defaultValue, "16");
  EXPECT_EQ(p.decls()[1].defaultValue, "0.25");
  EXPECT_EQ(p.decls()[2].defaultValue, "true");
  EXPECT_EQ(p.decls()[3].help, "quality");
}

TEST(Params, StartsAtDefaults) {
  const ParamSet p = makeParams();
  EXPECT_EQ(p.getInt("samples"), 16);
  EXPECT_DOUBLE_EQ(p.getFloat("alpha"), 0.25);
  EXPECT_TRUE(p.getBool("shadows"));
  EXPECT_EQ(p.getChoice("mode"), "fast");
  EXPECT_EQ(p.text("samples"), "16");
  EXPECT_TRUE(p.has("alpha"));
  EXPECT_FALSE(p.has("beta"));
  const ParamSet off("x", {ParamDecl::boolean("flag", false, "")});
  EXPECT_FALSE(off.getBool("flag"));
}

TEST(Params, SetParsesEachType) {
  ParamSet p = makeParams();
  p.set("samples", "256");
  EXPECT_EQ(p.getInt("samples"), 256);
  p.set("samples", "1");
  EXPECT_EQ(p.getInt("samples"), 1);
  p.set("samples", "+42");
  EXPECT_EQ(p.getInt("samples"), 42);
  p.set("samples", "16.0");  // integral, so accepted
  EXPECT_EQ(p.getInt("samples"), 16);
}

// Known bug (reported, not fixed here): set() validates the number strtod
// reads but stores the text as written, and getInt()/toJson() re-read it with
// std::stoi/stoll, which stop at 'e' or 'x': "1e2" validates as 100 but reads
// back as 1, "0x10" as 0. Enable once ParamSet::set stores canonical text.
TEST(Params, IntegerInExponentOrHexNotationReadsBackAsValidated) {
  ParamSet p = makeParams();
  p.set("samples", "1e2");
  EXPECT_EQ(p.getInt("samples"), 100);
  EXPECT_EQ(p.toJson()["samples"].get<int>(), 100);
  p.set("samples", "0x10");
  EXPECT_EQ(p.getInt("samples"), 16);
}

TEST(Params, SetParsesFloatsBoolsAndChoices) {
  ParamSet p = makeParams();
  p.set("alpha", "1.5");
  EXPECT_DOUBLE_EQ(p.getFloat("alpha"), 1.5);
  p.set("alpha", "0");
  EXPECT_DOUBLE_EQ(p.getFloat("alpha"), 0.0);
  p.set("alpha", "7.5e-1");
  EXPECT_DOUBLE_EQ(p.getFloat("alpha"), 0.75);
  p.set("shadows", "false");
  EXPECT_FALSE(p.getBool("shadows"));
  p.set("shadows", "1");
  EXPECT_TRUE(p.getBool("shadows"));
  EXPECT_EQ(p.text("shadows"), "true");  // normalised spelling
  p.set("shadows", "0");
  EXPECT_FALSE(p.getBool("shadows"));
  EXPECT_EQ(p.text("shadows"), "false");
  p.set("mode", "debug");
  EXPECT_EQ(p.getChoice("mode"), "debug");
}

TEST(Params, IntegerRejectsFractionsAndText) {
  ParamSet p = makeParams();
  const std::string frac = errorOf([&] { p.set("samples", "2.5"); });
  EXPECT_TRUE(contains(frac, "parameter 'samples'")) << frac;
  EXPECT_TRUE(contains(frac, "'2.5' is not an integer")) << frac;
  EXPECT_TRUE(contains(frac, "[1, 256]")) << frac;
  const std::string text = errorOf([&] { p.set("samples", "many"); });
  EXPECT_TRUE(contains(text, "'many'")) << text;
  EXPECT_TRUE(contains(errorOf([&] { p.set("samples", ""); }), "not an integer"));
  EXPECT_TRUE(contains(errorOf([&] { p.set("samples", "12abc"); }), "not an integer"));
  EXPECT_EQ(p.getInt("samples"), 16) << "a rejected value must not be stored";
}

TEST(Params, OutOfRangeStatesTheRange) {
  ParamSet p = makeParams();
  const std::string low = errorOf([&] { p.set("samples", "0"); });
  EXPECT_EQ(low, "technique 'demo' parameter 'samples' = 0 is out of range [1, 256]");
  const std::string high = errorOf([&] { p.set("samples", "257"); });
  EXPECT_TRUE(contains(high, "is out of range [1, 256]")) << high;
  const std::string real = errorOf([&] { p.set("alpha", "1.5001"); });
  EXPECT_TRUE(contains(real, "parameter 'alpha' = 1.5001 is out of range [0, 1.5]")) << real;
  EXPECT_TRUE(contains(errorOf([&] { p.set("alpha", "-1e-9"); }), "out of range [0, 1.5]"));
  EXPECT_EQ(p.getInt("samples"), 16);
  EXPECT_DOUBLE_EQ(p.getFloat("alpha"), 0.25);
}

TEST(Params, FloatRejectsNonFinite) {
  ParamSet p = makeParams();
  for (const char* bad : {"nan", "inf", "-inf", "abc", "", "0.5x"}) {
    const std::string msg = errorOf([&] { p.set("alpha", bad); });
    EXPECT_TRUE(contains(msg, "is not a number (range [0, 1.5])")) << bad << ": " << msg;
  }
}

TEST(Params, BoolAndChoiceListAllowedValues) {
  ParamSet p = makeParams();
  const std::string b = errorOf([&] { p.set("shadows", "yes"); });
  EXPECT_TRUE(contains(b, "'yes' is not a boolean (allowed: true, false)")) << b;
  const std::string c = errorOf([&] { p.set("mode", "slow"); });
  EXPECT_EQ(c, "technique 'demo' parameter 'mode': unknown value 'slow' (one of: fast, exact, debug)");
  EXPECT_TRUE(contains(errorOf([&] { p.set("mode", "FAST"); }), "unknown value 'FAST'"));  // case-sensitive
  EXPECT_EQ(p.getChoice("mode"), "fast");
  EXPECT_TRUE(p.getBool("shadows"));
}

TEST(Params, UnknownParameterListsKnownNames) {
  ParamSet p = makeParams();
  const std::string msg = errorOf([&] { p.set("sample", "4"); });
  EXPECT_EQ(msg, "technique 'demo' has no parameter 'sample' (parameters: samples, alpha, shadows, mode)");
  EXPECT_TRUE(contains(errorOf([&] { (void)p.getInt("nope"); }), "(parameters: samples, alpha, shadows, mode)"));
  EXPECT_TRUE(contains(errorOf([&] { (void)p.text("nope"); }), "has no parameter 'nope'"));
  ParamSet none("accelerator 'none'", {});
  EXPECT_EQ(errorOf([&] { none.set("depth", "3"); }),
            "accelerator 'none' has no parameter 'depth' (parameters: none)");
}

TEST(Params, AssignParsesNameEqualsValue) {
  ParamSet p = makeParams();
  p.assign("samples=64");
  EXPECT_EQ(p.getInt("samples"), 64);
  p.assign("mode=exact");
  EXPECT_EQ(p.getChoice("mode"), "exact");
  p.assign("alpha=1e-1");
  EXPECT_DOUBLE_EQ(p.getFloat("alpha"), 0.1);
}

TEST(Params, AssignErrors) {
  ParamSet p = makeParams();
  EXPECT_EQ(errorOf([&] { p.assign("samples"); }), "--set expects name=value, got 'samples'");
  EXPECT_EQ(errorOf([&] { p.assign("=4"); }), "--set expects name=value, got '=4'");
  EXPECT_EQ(errorOf([&] { p.assign(""); }), "--set expects name=value, got ''");
  // The value is everything after the first '='.
  EXPECT_TRUE(contains(errorOf([&] { p.assign("mode=fast=exact"); }), "unknown value 'fast=exact'"));
  EXPECT_TRUE(contains(errorOf([&] { p.assign("samples="); }), "not an integer"));
  EXPECT_TRUE(contains(errorOf([&] { p.assign("colour=red"); }), "has no parameter 'colour'"));
  EXPECT_EQ(p.getInt("samples"), 16);
}

TEST(Params, ToJsonHasTypedValues) {
  ParamSet p = makeParams();
  nlohmann::json j = p.toJson();
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j.size(), 4u);
  ASSERT_TRUE(j["samples"].is_number_integer());
  EXPECT_EQ(j["samples"].get<int>(), 16);
  ASSERT_TRUE(j["alpha"].is_number_float());
  EXPECT_DOUBLE_EQ(j["alpha"].get<double>(), 0.25);
  ASSERT_TRUE(j["shadows"].is_boolean());
  EXPECT_TRUE(j["shadows"].get<bool>());
  ASSERT_TRUE(j["mode"].is_string());
  EXPECT_EQ(j["mode"].get<std::string>(), "fast");

  p.set("samples", "3");
  p.set("alpha", "1");
  p.set("shadows", "0");
  p.set("mode", "debug");
  j = p.toJson();
  EXPECT_EQ(j["samples"].get<int>(), 3);
  ASSERT_TRUE(j["alpha"].is_number_float()) << "a float stays a float even when written as an integer";
  EXPECT_DOUBLE_EQ(j["alpha"].get<double>(), 1.0);
  EXPECT_FALSE(j["shadows"].get<bool>());
  EXPECT_EQ(j["mode"].get<std::string>(), "debug");
  EXPECT_TRUE(ParamSet().toJson().is_object());
  EXPECT_TRUE(ParamSet().toJson().empty());
}

}  // namespace
}  // namespace ll
