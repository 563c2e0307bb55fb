#include "gui/legend_labels.h"

#include <gtest/gtest.h>

namespace ll::gui {
namespace {

// 10 units per character, as a monospace font would draw them.
float mono(std::string_view s) { return 10.0f * static_cast<float>(s.size()); }

std::vector<std::string> texts(const std::vector<LegendLabel>& labels) {
  std::vector<std::string> t;
  for (const LegendLabel& l : labels) t.push_back(l.text);
  return t;
}

void expectApart(const std::vector<LegendLabel>& labels, float width, float gap) {
  for (size_t i = 0; i < labels.size(); ++i) {
    EXPECT_GE(labels[i].x, 0.0f);
    EXPECT_LE(labels[i].x + mono(labels[i].text), width + 1e-3f);
    if (i > 0) {
      EXPECT_GE(labels[i].x, labels[i - 1].x + mono(labels[i - 1].text) + gap) << labels[i].text;
    }
  }
}

TEST(LegendLabels, AWideBarShowsZeroTheMiddleAndTheTopWithItsNote) {
  const auto labels = legendLabels(600.0f, 41.5f, true, 8.0f, mono);
  EXPECT_EQ(texts(labels), (std::vector<std::string>{"0", "20.8", "41.5 (auto, 99th pct)"}));
  EXPECT_FLOAT_EQ(labels[1].x, (600.0f - 40.0f) / 2);
  EXPECT_FLOAT_EQ(labels[2].x, 600.0f - 210.0f);
  expectApart(labels, 600.0f, 8.0f);
}

// At UI scale 2 a pane's bar was too short: "20.5" was drawn over "41.5 (auto, 99th pct)".
TEST(LegendLabels, ANarrowBarDropsTheMiddleThenTheNoteAndNeverOverlaps) {
  const auto noMiddle = legendLabels(300.0f, 41.5f, true, 8.0f, mono);
  EXPECT_EQ(texts(noMiddle), (std::vector<std::string>{"0", "41.5 (auto, 99th pct)"}));
  expectApart(noMiddle, 300.0f, 8.0f);
  const auto noNote = legendLabels(150.0f, 41.5f, true, 8.0f, mono);
  EXPECT_EQ(texts(noNote), (std::vector<std::string>{"0", "20.8", "41.5"}));
  expectApart(noNote, 150.0f, 8.0f);
  const auto ends = legendLabels(70.0f, 41.5f, true, 8.0f, mono);
  EXPECT_EQ(texts(ends), (std::vector<std::string>{"0", "41.5"}));
  expectApart(ends, 70.0f, 8.0f);
  EXPECT_EQ(texts(legendLabels(30.0f, 41.5f, true, 8.0f, mono)), (std::vector<std::string>{"0"}));
  EXPECT_EQ(texts(legendLabels(600.0f, 3.0f, false, 8.0f, mono)), (std::vector<std::string>{"0", "1.5", "3"}));
}

}  // namespace
}  // namespace ll::gui
