// The screenshot sidecar is written whatever bytes the messages and paths
// hold: text that is not UTF-8 (a Latin-1 scene description or file name)
// becomes U+FFFD instead of ending the program.
#include "gui/screenshot.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "gui/app_actions.h"

namespace ll::gui {
namespace {

TEST(ScreenshotSidecar, TextThatIsNotUtf8IsReplacedNotFatal) {
  AppState app;
  initPanes(app);
  app.scenePath = "/tmp/sz\xe8ne_f\xfcr.json";
  addMessage(app, "f\xfcr: description in Latin-1");
  const std::string png = (std::filesystem::path(testing::TempDir()) / "lightlab_sidecar_test.png").string();
  const std::string sidecar = saveScreenshotSidecar(app, png, 640, 480, 1.0f);
  std::ifstream in(sidecar);
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(text.str());  // valid UTF-8 JSON
  EXPECT_EQ(j["scene"], "/tmp/sz\xef\xbf\xbdne_f\xef\xbf\xbdr.json");
  EXPECT_EQ(j["messages"].back()["text"], "f\xef\xbf\xbdr: description in Latin-1");
  std::filesystem::remove(sidecar);
}

}  // namespace
}  // namespace ll::gui
