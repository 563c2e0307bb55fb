// The pickers: short names relative to data/, bundled scenes before the
// build's generated ones, presets grouped, search by words.
#include "gui/file_picker.h"

#include <gtest/gtest.h>

#include "gui/gui_app.h"

namespace ll::gui {
namespace {

TEST(FilePicker, ShortNamesBundledFirstGroupedAndSorted) {
  const auto entries = pickerEntries({"/src/build/data/scenes/bunny_big.json", "/src/data/scenes/whitted_1980.json",
                                      "/src/data/scenes/cornell_box.json", "/src/data/presets/assignments/A2.json",
                                      "/src/data/presets/bvh_cost.json", "/tmp/mine.json",
                                      "data/scenes/cornell_box.json"});
  std::vector<std::string> names, groups;
  for (const auto& e : entries) {
    names.push_back(e.name);
    groups.push_back(e.group);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"scenes/cornell_box.json", "scenes/whitted_1980.json",
                                              "presets/bvh_cost.json", "presets/assignments/A2.json",
                                              "scenes/bunny_big.json", "mine.json"}));
  EXPECT_EQ(groups, (std::vector<std::string>{"bundled scenes", "bundled scenes", "presets", "assignment presets",
                                               "generated scenes (build)", "other"}));
}

TEST(FilePicker, SearchMatchesEveryWordCaseInsensitively) {
  const PickerEntry e{"/x/data/scenes/whitted_1980.json", "scenes/whitted_1980.json", "bundled scenes"};
  EXPECT_TRUE(pickerMatches(e, ""));
  EXPECT_TRUE(pickerMatches(e, "Whitted"));
  EXPECT_TRUE(pickerMatches(e, "1980 whit"));
  EXPECT_FALSE(pickerMatches(e, "whitted bunny"));
}

TEST(FilePicker, FindsTheBundledPresetsAndNoScenes) {
  const auto files = findPresetFiles({std::string(LIGHTLAB_DATA_DIR) + "/presets"});
  ASSERT_FALSE(files.empty());
  bool assignment = false;
  for (const auto& f : files) {
    EXPECT_EQ(f.find("/scenes/"), std::string::npos) << f;
    if (f.find("/presets/assignments/") != std::string::npos) assignment = true;
  }
  EXPECT_TRUE(assignment);
}

}  // namespace
}  // namespace ll::gui
