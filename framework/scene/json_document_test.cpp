#include "scene/json_document.h"

#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "test_support.h"

#include "core/error.h"

namespace ll {
namespace {

// 1-based line and column of the n-th (0-based) occurrence of `needle` in
// `text`, computed independently of the parser.
std::pair<int, int> positionOf(const std::string& text, const std::string& needle, int occurrence = 0) {
  size_t at = text.find(needle);
  for (int i = 0; i < occurrence && at != std::string::npos; ++i) at = text.find(needle, at + 1);
  EXPECT_NE(at, std::string::npos) << needle;
  int line = 1, col = 1;
  for (size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return {line, col};
}

using testing_support::contains;
using testing_support::errorOf;

const std::string kScene = R"({
  "camera": {"eye": [0, 0, 4], "fov_y_deg": 40},
  "objects": [
    {"type": "sphere", "radius": 1},
    {"type": "quad", "vertices": [[0, 0, 0], {"x": [1, 2]}, [5, 6, 7]]},
    {
      "type": "sphere",
      "radius": 2,
      "nested": {"deep": {"deeper": [{"k": 1}, {"k": 2}]}}
    }
  ],
  "a/b~c": true
}
)";

TEST(JsonDocument, LocatesKeysAtTheirOpeningQuote) {
  const JsonDocument doc(kScene, "scene.json");
  EXPECT_EQ(doc.locate(""), std::make_pair(1, 1));
  EXPECT_EQ(doc.locate("/camera"), std::make_pair(2, 3));
  EXPECT_EQ(doc.locate("/camera/eye"), std::make_pair(2, 14));
  EXPECT_EQ(doc.locate("/camera/fov_y_deg"), positionOf(kScene, "\"fov_y_deg\""));
  EXPECT_EQ(doc.locate("/objects"), std::make_pair(3, 3));
  EXPECT_EQ(doc.locate("/objects/0/type"), positionOf(kScene, "\"type\"", 0));
  EXPECT_EQ(doc.locate("/objects/0/radius"), positionOf(kScene, "\"radius\"", 0));
  EXPECT_EQ(doc.locate("/objects/1/type"), positionOf(kScene, "\"type\"", 1));
  EXPECT_EQ(doc.locate("/objects/1/vertices"), positionOf(kScene, "\"vertices\""));
}

TEST(JsonDocument, LocatesArrayElementsAfterNestedContainers) {
  const JsonDocument doc(kScene, "scene.json");
  // Elements that follow nested objects and arrays keep the right index.
  EXPECT_EQ(doc.locate("/objects/0"), std::make_pair(4, 5));
  EXPECT_EQ(doc.locate("/objects/1"), std::make_pair(5, 5));
  EXPECT_EQ(doc.locate("/objects/2"), std::make_pair(6, 5));
  EXPECT_EQ(doc.locate("/objects/2/type"), std::make_pair(7, 7));
  EXPECT_EQ(doc.locate("/objects/2/radius"), std::make_pair(8, 7));
  EXPECT_EQ(doc.locate("/objects/2/nested/deep/deeper"), positionOf(kScene, "\"deeper\""));
  EXPECT_EQ(doc.locate("/objects/2/nested/deep/deeper/1"), positionOf(kScene, "{\"k\": 2}"));
  EXPECT_EQ(doc.locate("/objects/2/nested/deep/deeper/1/k"), positionOf(kScene, "\"k\"", 1));
  EXPECT_EQ(doc.locate("/objects/1/vertices/0"), positionOf(kScene, "[0, 0, 0]"));
  EXPECT_EQ(doc.locate("/objects/1/vertices/1"), positionOf(kScene, "{\"x\""));
  EXPECT_EQ(doc.locate("/objects/1/vertices/1/x"), positionOf(kScene, "\"x\""));
  EXPECT_EQ(doc.locate("/objects/1/vertices/2"), positionOf(kScene, "[5, 6, 7]"));
  EXPECT_EQ(doc.locate("/a~1b~0c"), positionOf(kScene, "\"a/b~c\""));  // escaped pointer tokens
}

TEST(JsonDocument, LocateFallsBackToNearestAncestor) {
  const JsonDocument doc(kScene, "scene.json");
  EXPECT_EQ(doc.locate("/objects/2/missing"), doc.locate("/objects/2"));
  EXPECT_EQ(doc.locate("/objects/7"), doc.locate("/objects"));
  EXPECT_EQ(doc.locate("/nothing/at/all"), std::make_pair(1, 1));
}

TEST(JsonDocument, LocatesElementsOnTheirOwnLines) {
  const std::string text = "[\n  {\"a\": 1},\n\n  [\n    {}\n  ],\n  {\"b\": {\"c\": 3}}\n]";
  const JsonDocument doc(text, "list.json");
  EXPECT_EQ(doc.locate("/0"), std::make_pair(2, 3));
  EXPECT_EQ(doc.locate("/1"), std::make_pair(4, 3));
  EXPECT_EQ(doc.locate("/1/0"), std::make_pair(5, 5));
  EXPECT_EQ(doc.locate("/2"), std::make_pair(7, 3));
  EXPECT_EQ(doc.locate("/2/b/c"), positionOf(text, "\"c\""));
}

// Known bug (reported, not fixed here): a scalar array element is located at
// the last character the lexer read, not at the token's start: one past a
// number (the lexer's look-ahead: ',' ']' or the newline), the closing quote
// of a string, the last letter of true/false/null. Lines are right, columns
// are not. Enable once LocatingSax records the token start.
TEST(JsonDocument, DISABLED_LocatesScalarArrayElementsAtTheirFirstCharacter) {
  const std::string text = "{\"eye\": [0, 10, 4], \"s\": [\"ab\", \"cd\"], \"b\": [true],\n \"l\": [\n  22\n ]}";
  const JsonDocument doc(text, "s.json");
  EXPECT_EQ(doc.locate("/eye/0"), std::make_pair(1, 10));
  EXPECT_EQ(doc.locate("/eye/1"), std::make_pair(1, 13));
  EXPECT_EQ(doc.locate("/s/1"), positionOf(text, "\"cd\""));
  EXPECT_EQ(doc.locate("/b/0"), positionOf(text, "true"));
  EXPECT_EQ(doc.locate("/l/0"), std::make_pair(3, 3));
}

TEST(JsonDocument, FailNamesFileLineAndColumn) {
  const JsonDocument doc(kScene, "dir/scene.json");
  EXPECT_EQ(errorOf([&] { doc.fail("/objects/2/radius", "radius is wrong"); }),
            "dir/scene.json:8:7: radius is wrong");
  EXPECT_EQ(doc.file(), "dir/scene.json");
  EXPECT_EQ(doc.root()["objects"][2]["radius"].get<int>(), 2);
}

TEST(JsonDocument, MalformedJsonMissingCommaHint) {
  const std::string text = "{\n  \"a\": 1\n  \"b\": 2\n}\n";
  const std::string msg = errorOf([&] { JsonDocument(text, "m.json"); });
  EXPECT_EQ(msg.rfind("m.json:3:3: malformed JSON: ", 0), 0u) << msg;
  EXPECT_TRUE(contains(msg, "(a missing comma before it?)")) << msg;
  EXPECT_FALSE(contains(msg, "\n")) << msg;
}

TEST(JsonDocument, MissingCommaInArrays) {
  const std::string numbers = errorOf([&] { JsonDocument("[1, 2 3]", "a.json"); });
  EXPECT_EQ(numbers.rfind("a.json:1:7: malformed JSON: ", 0), 0u) << numbers;
  EXPECT_TRUE(contains(numbers, "missing comma")) << numbers;
  const std::string objects = errorOf([&] { JsonDocument("[{\"a\": 1}\n {\"b\": 2}]", "o.json"); });
  EXPECT_EQ(objects.rfind("o.json:", 0), 0u) << objects;
  EXPECT_TRUE(contains(objects, "missing comma")) << objects;
  const std::string strings = errorOf([&] { JsonDocument("{\"k\": [\"x\" \"yy\"]}", "s.json"); });
  EXPECT_EQ(strings.rfind("s.json:1:12: malformed JSON: ", 0), 0u) << strings;
  EXPECT_TRUE(contains(strings, "missing comma")) << strings;
}

TEST(JsonDocument, OtherSyntaxErrorsHaveNoCommaHint) {
  for (const char* text : {"{\"a\": 1,}", "{\"a\" 1}", "{\"a\": tru}", "[1, 2", ""}) {
    const std::string msg = errorOf([&] { JsonDocument(text, "x.json"); });
    EXPECT_EQ(msg.rfind("x.json:1:", 0), 0u) << text << " -> " << msg;
    EXPECT_TRUE(contains(msg, ": malformed JSON: ")) << msg;
    EXPECT_FALSE(contains(msg, "missing comma")) << text << " -> " << msg;
  }
}

// Known bug (reported, not fixed here): when the offending token is a
// structural character ('{' '[' '}' ']' ',' ':'), nlohmann's token string is
// not reset, so it still holds the previous scalar and the whitespace since,
// with each control character escaped to "<U+000A>"; backing up by its length
// lands too early (here 1:1 and 1:8 instead of 2:2 and 1:11). A missing comma
// between two objects of "objects" is the commonest scene-file typo.
TEST(JsonDocument, DISABLED_SyntaxErrorAtStructuralTokenIsLocatedAtThatToken) {
  EXPECT_EQ(errorOf([&] { JsonDocument("[{\"a\": 1}\n {\"b\": 2}]", "o.json"); }).rfind("o.json:2:2:", 0), 0u);
  EXPECT_EQ(errorOf([&] { JsonDocument("[{\"a\": 1} {\"b\": 2}]", "o.json"); }).rfind("o.json:1:11:", 0), 0u);
  EXPECT_EQ(errorOf([&] { JsonDocument("{\"a\": 1,\n}", "t.json"); }).rfind("t.json:2:1:", 0), 0u);
  EXPECT_EQ(errorOf([&] { JsonDocument("{\"a\": [1,\n  2\n  [3]]}", "a.json"); }).rfind("a.json:3:3:", 0), 0u);
}

TEST(JsonDocument, LoadReadsFileAndNamesItInErrors) {
  const std::string path = std::string(LIGHTLAB_DATA_DIR) + "/scenes/tests/bad/malformed_json.json";
  const std::string msg = errorOf([&] { JsonDocument::load(path); });
  EXPECT_EQ(msg.rfind(path + ":6:5: malformed JSON: ", 0), 0u) << msg;
  EXPECT_TRUE(contains(msg, "missing comma")) << msg;
  const std::string missing = std::string(LIGHTLAB_DATA_DIR) + "/scenes/no_such_file.json";
  EXPECT_EQ(errorOf([&] { JsonDocument::load(missing); }), missing + ": no such JSON file");
  const JsonDocument ok = JsonDocument::load(std::string(LIGHTLAB_DATA_DIR) + "/scenes/tests/sphere_point_light.json");
  EXPECT_EQ(ok.locate("/objects/0/radius"), std::make_pair(35, 7));
  EXPECT_EQ(ok.locate("/lights/0"), std::make_pair(23, 5));
}

TEST(JsonNode, TypedGettersReportAtTheValue) {
  const std::string text = R"({
  "n": 2.5,
  "i": 3,
  "f": 1.5,
  "b": true,
  "s": "text",
  "v": [1, 2, 3],
  "short": [1, 2],
  "neg": [0.5, -1, 0]
})";
  const JsonDocument doc(text, "t.json");
  const JsonNode root(doc, doc.root(), "", "cfg");
  EXPECT_FLOAT_EQ(root.number("n", 0.0f, 10.0f), 2.5f);
  EXPECT_FLOAT_EQ(root.number("absent", 7.0f, 0.0f, 10.0f), 7.0f);
  EXPECT_EQ(root.integer("i", 0, 0, 10), 3);
  EXPECT_EQ(root.integer("absent", 9, 0, 10), 9);
  EXPECT_TRUE(root.boolean("b", false));
  EXPECT_EQ(root.string("s"), "text");
  EXPECT_EQ(root.vec3("v"), Vec3(1, 2, 3));
  EXPECT_EQ(root.vec3("absent", Vec3(4, 5, 6)), Vec3(4, 5, 6));
  EXPECT_EQ(root.color("absent", Rgb(0.5f)), Rgb(0.5f));

  EXPECT_EQ(errorOf([&] { root.number("n", 3.0f, 10.0f); }), "t.json:2:3: cfg.n = 2.5 is out of range [3, 10]");
  EXPECT_EQ(errorOf([&] { root.integer("f", 0, 0, 10); }), "t.json:4:3: cfg.f must be an integer, got 1.5");
  EXPECT_EQ(errorOf([&] { root.integer("i", 0, 5, 10); }), "t.json:3:3: cfg.i = 3 is out of range [5, 10]");
  EXPECT_EQ(errorOf([&] { root.boolean("s", false); }), "t.json:6:3: cfg.s must be true or false, got a string");
  EXPECT_EQ(errorOf([&] { root.string("b"); }), "t.json:5:3: cfg.b must be a string, got a boolean");
  EXPECT_EQ(errorOf([&] { root.number("s", 0.0f, 1.0f); }), "t.json:6:3: cfg.s must be a number, got a string");
  EXPECT_EQ(errorOf([&] { root.vec3("short"); }),
            "t.json:8:3: cfg.short must be an array of 3 numbers [x, y, z], got an array of 2");
  EXPECT_EQ(errorOf([&] { root.color("neg", Rgb(0.0f)); }),
            "t.json:9:3: cfg.neg must have every channel >= 0, got [0.5,-1,0]");
  EXPECT_EQ(errorOf([&] { root.child("missing"); }), "t.json:1:1: cfg needs the key 'missing'");
  EXPECT_EQ(errorOf([&] { root.child("v").requireObject(); }), "t.json:7:3: cfg.v must be an object, got an array");
  EXPECT_EQ(errorOf([&] { root.child("s").requireArray(); }), "t.json:6:3: cfg.s must be an array, got a string");
}

TEST(JsonNode, NumbersBeyondTheFloatRangeAreRejectedNotMadeInfinite) {
  // 1e39 is a finite double but no float: it used to become +inf (a sphere of infinite radius rendered).
  const std::string text = R"({
  "big": 1e39,
  "v": [0, -3.5e38, 0],
  "edge": 3.4e38
})";
  const JsonDocument doc(text, "t.json");
  const JsonNode root(doc, doc.root(), "", "cfg");
  EXPECT_EQ(errorOf([&] { root.number("big", 0.0f, kInfinity); }),
            "t.json:2:3: cfg.big = 1e+39 is not a finite float (|x| <= 3.4e38)");
  EXPECT_TRUE(contains(errorOf([&] { root.vec3("v"); }), "cfg.v[1] = -3.5e+38 is not a finite float (|x| <= 3.4e38)"));
  EXPECT_FLOAT_EQ(root.number("edge", 0.0f, kInfinity), 3.4e38f);
}

TEST(JsonNode, AllowOnlyNamesTheUnknownKeyAndListsAllowed) {
  const std::string text = "{\n  \"eye\": [0, 0, 1],\n  \"fovy\": 40\n}";
  const JsonDocument doc(text, "c.json");
  const JsonNode cam(doc, doc.root(), "", "scene.camera");
  EXPECT_EQ(errorOf([&] { cam.allowOnly({"eye", "target", "fov_y_deg"}); }),
            "c.json:3:3: unknown key 'fovy' in scene.camera (allowed: eye, target, fov_y_deg)");
  EXPECT_NO_THROW(cam.allowOnly({"eye", "fovy"}));
  EXPECT_EQ(cam.child("eye").what(), "scene.camera.eye");
  EXPECT_EQ(cam.child("eye").at(2).what(), "scene.camera.eye[2]");
  EXPECT_EQ(cam.child("eye").at(2).pointer(), "/eye/2");
}

}  // namespace
}  // namespace ll
