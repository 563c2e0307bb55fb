#include "gui/caption_wrap.h"

#include <gtest/gtest.h>

namespace ll::gui {
namespace {

// A monospaced font: every character 1 unit wide.
float chars(std::string_view s) { return static_cast<float>(s.size()); }

using Lines = std::vector<std::string>;

std::string withoutSpaces(std::string s) {
  std::erase(s, ' ');
  return s;
}

TEST(CaptionWrap, ALineThatFitsIsKeptAsItIs) {
  EXPECT_EQ(wrapCaptionLine("pass 3/16  1.20 s", 17, chars), Lines{"pass 3/16  1.20 s"});
  EXPECT_EQ(wrapCaptionLine("", 5, chars), Lines{""});
}

// The line the previous wrapping broke after "0.": numbers stay whole.
TEST(CaptionWrap, BreaksBetweenFieldsNeverInsideANumber) {
  const std::string line = "pass 16/16  0.26 s  3.41 Mrays/s  done";
  EXPECT_EQ(wrapCaptionLine(line, 20, chars), (Lines{"pass 16/16  0.26 s", "3.41 Mrays/s  done"}));
  for (float width = 4; width < 40; ++width)
    for (const std::string& l : wrapCaptionLine(line, width, chars)) {
      EXPECT_NE(l.back(), '.') << "width " << width;
      EXPECT_NE(l.front(), ' ') << "width " << width;
      EXPECT_NE(l.back(), ' ') << "width " << width;
    }
}

TEST(CaptionWrap, AFieldWiderThanTheLineBreaksAtItsSpaces) {
  EXPECT_EQ(wrapCaptionLine("vs A: relMSE 0.0012  SSIM 0.9981", 12, chars),
            (Lines{"vs A: relMSE", "0.0012", "SSIM 0.9981"}));
  // A single word wider than the line is not cut.
  EXPECT_EQ(wrapCaptionLine("reference A4.3_KdTreeBuild", 10, chars), (Lines{"reference", "A4.3_KdTreeBuild"}));
}

// "/" (technique / accelerator) starts the next line; "|" only separates, and a line break does that.
TEST(CaptionWrap, ASlashStartsTheNextLineABarIsDropped) {
  EXPECT_EQ(wrapCaptionLine("A  path  /  bvh  |  64 spp", 11, chars), (Lines{"A  path", "/  bvh", "64 spp"}));
  EXPECT_EQ(wrapCaptionLine("A  path  /  bvh  |  strategy mis", 12, chars), (Lines{"A  path", "/  bvh", "strategy mis"}));
}

// The time line keeps each term of its sum whole.
TEST(CaptionWrap, TheTimeLineBreaksBetweenTerms) {
  EXPECT_EQ(wrapCaptionLine("time: build 0.06  + preview 0.01  + prepare 0.00  + passes 0.29 s", 50, chars),
            (Lines{"time: build 0.06  + preview 0.01  + prepare 0.00", "+ passes 0.29 s"}));
}

TEST(CaptionWrap, ABarBetweenFieldsOnOneLineStays) {
  EXPECT_EQ(wrapCaptionLine("your A2.4  |  reference A2.1 A2.5", 40, chars), Lines{"your A2.4  |  reference A2.1 A2.5"});
  EXPECT_EQ(wrapCaptionLine("A  raycast  /  bvh  |  64 spp  |  x", 30, chars), (Lines{"A  raycast  /  bvh  |  64 spp", "x"}));
}

TEST(CaptionWrap, NoTextButASeparatingBarIsLost) {
  const std::string line = "time: build 0.12 + preview 0.30 + prepare 0.01 + passes 2.40 s";
  for (float width = 1; width < 70; ++width) {
    std::string joined;
    for (const std::string& l : wrapCaptionLine(line, width, chars)) joined += l + " ";
    EXPECT_EQ(withoutSpaces(joined), withoutSpaces(line)) << "width " << width;
  }
}

}  // namespace
}  // namespace ll::gui
