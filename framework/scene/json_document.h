// A parsed JSON file that remembers where every value came from, so loaders
// can say "scene.json:12:7: radius must be > 0" rather than only what is
// wrong. Parsing is nlohmann-json's SAX parser; this file only records the
// byte offset of each key and value by JSON pointer.
#pragma once

#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/math.h"

namespace ll {

class JsonDocument {
 public:
  // Parses text read from `file` (used in messages). Throws UserError with
  // file:line:col on malformed JSON.
  JsonDocument(std::string text, std::string file);
  static JsonDocument load(const std::string& path);

  const nlohmann::json& root() const { return root_; }
  const std::string& file() const { return file_; }
  // 1-based line and column of the key or value at a JSON pointer ("/camera/eye").
  std::pair<int, int> locate(const std::string& pointer) const;
  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const;

 private:
  std::string file_;
  std::string text_;
  nlohmann::json root_;
  std::map<std::string, size_t> offsets_;
};

// A read-only view of one value inside a JsonDocument, with typed getters that
// validate and report errors at the value's position.
class JsonNode {
 public:
  JsonNode(const JsonDocument& doc, const nlohmann::json& value, std::string pointer, std::string what)
      : doc_(&doc), value_(&value), pointer_(std::move(pointer)), what_(std::move(what)) {}

  const nlohmann::json& json() const { return *value_; }
  const std::string& pointer() const { return pointer_; }
  const std::string& what() const { return what_; }
  bool has(const std::string& key) const { return value_->is_object() && value_->contains(key); }

  // Requires an object / array / string; fails naming the expected type.
  void requireObject() const;
  void requireArray() const;
  // Fails on the first key not in `allowed`, listing the allowed keys.
  void allowOnly(std::initializer_list<const char*> allowed) const;
  JsonNode child(const std::string& key) const;  // required member
  JsonNode at(size_t index) const;               // array element
  size_t size() const { return value_->size(); }

  // Typed members: `key` missing -> fallback (if given) or an error.
  float number(const std::string& key, float min, float max) const;
  float number(const std::string& key, float fallback, float min, float max) const;
  int integer(const std::string& key, int fallback, int min, int max) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::string string(const std::string& key) const;
  Vec3 vec3(const std::string& key) const;
  Vec3 vec3(const std::string& key, Vec3 fallback) const;
  Rgb color(const std::string& key, Rgb fallback) const;  // every channel >= 0

  // This value read as a number / vec3 / vec2.
  float asNumber() const;
  Vec3 asVec3() const;
  Vec2 asVec2() const;

  [[noreturn]] void fail(const std::string& message) const { doc_->fail(pointer_, message); }

 private:
  const JsonDocument* doc_;
  const nlohmann::json* value_;
  std::string pointer_;
  std::string what_;  // human name for messages, e.g. "camera" or "objects[3]"
};

}  // namespace ll
