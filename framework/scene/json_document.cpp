#include "scene/json_document.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "core/files.h"
#include "core/utf8.h"

namespace ll {

namespace {

// A char iterator that publishes how far the parser has read, so SAX events
// can be given the position of the token just consumed.
struct TrackingIterator {
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  const char* p = nullptr;
  const char** furthest = nullptr;

  reference operator*() const { return *p; }
  TrackingIterator& operator++() {
    ++p;
    if (p > *furthest) *furthest = p;
    return *this;
  }
  TrackingIterator operator++(int) {
    TrackingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const TrackingIterator& o) const { return p == o.p; }
  bool operator!=(const TrackingIterator& o) const { return p != o.p; }
};

std::string escapePointerToken(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

// Forwards every event to nlohmann's DOM builder and records the offset of
// each key and value under its JSON pointer.
class LocatingSax {
 public:
  using Json = nlohmann::json;
  LocatingSax(Json& result, const char* begin, const char** cursor, std::map<std::string, size_t>& offsets)
      : dom_(result, false), begin_(begin), cursor_(cursor), offsets_(offsets) {}

  bool null() { return value() && dom_.null(); }
  bool boolean(bool v) { return value() && dom_.boolean(v); }
  bool number_integer(Json::number_integer_t v) { return value() && dom_.number_integer(v); }
  bool number_unsigned(Json::number_unsigned_t v) { return value() && dom_.number_unsigned(v); }
  bool number_float(Json::number_float_t v, const std::string& s) { return value() && dom_.number_float(v, s); }
  bool string(std::string& v) { return value() && dom_.string(v); }
  bool binary(Json::binary_t& v) { return value() && dom_.binary(v); }
  bool start_object(std::size_t n) {
    value();
    frames_.push_back({false, -1, {}});
    return dom_.start_object(n);
  }
  bool key(std::string& k) {
    frames_.back().key = k;
    record(pointer(), k.size() + 1);  // point at the key's opening quote
    return dom_.key(k);
  }
  bool end_object() {
    frames_.pop_back();
    return dom_.end_object();
  }
  bool start_array(std::size_t n) {
    value();
    frames_.push_back({true, -1, {}});
    return dom_.start_array(n);
  }
  bool end_array() {
    frames_.pop_back();
    return dom_.end_array();
  }
  bool parse_error(std::size_t position, const std::string& token, const nlohmann::detail::exception& ex) {
    errorOffset = position;
    errorToken = token;
    errorMessage = ex.what();
    return false;
  }

  size_t errorOffset = 0;
  std::string errorToken, errorMessage;

 private:
  struct Frame {
    bool isArray;
    long index;  // of the current element; -1 before the first
    std::string key;
  };
  std::string pointer() const {
    std::string p;
    for (const Frame& f : frames_) p += "/" + (f.isArray ? std::to_string(f.index) : escapePointerToken(f.key));
    return p;
  }
  // Records the offset of the token just read, moved back by `back` characters.
  void record(const std::string& ptr, size_t back = 0) {
    const std::ptrdiff_t at = *cursor_ - begin_ - 1 - static_cast<std::ptrdiff_t>(back);
    offsets_.emplace(ptr, static_cast<size_t>(std::max<std::ptrdiff_t>(0, at)));
  }
  // Called at the start of every value: moves to the next array element and records it.
  bool value() {
    if (!frames_.empty() && frames_.back().isArray) {
      ++frames_.back().index;
      record(pointer());
    } else if (frames_.empty()) {
      record("");
    }
    return true;
  }

  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  const char* begin_;
  const char** cursor_;
  std::map<std::string, size_t>& offsets_;
  std::vector<Frame> frames_;
};

std::pair<int, int> lineColumn(const std::string& text, size_t offset) {
  offset = std::min(offset, text.size());
  int line = 1, col = 1;
  for (size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return {line, col};
}

}  // namespace

JsonDocument::JsonDocument(std::string text, std::string file) : file_(std::move(file)), text_(std::move(text)) {
  rejectNulBytes(text_, file_, "JSON file");
  const char* begin = text_.data();
  const char* cursor = begin;
  LocatingSax sax(root_, begin, &cursor, offsets_);
  TrackingIterator first{begin, &cursor}, last{begin + text_.size(), &cursor};
  const bool ok = nlohmann::json::sax_parse(first, last, &sax);
  if (!ok) {
    // nlohmann reports the offset just past the offending token: point at its start.
    size_t tokenStart = sax.errorOffset > sax.errorToken.size() ? sax.errorOffset - sax.errorToken.size() : 0;
    std::string detail = sax.errorMessage;
    const size_t colon = detail.find(": ", detail.find("column"));
    if (colon != std::string::npos) detail = detail.substr(colon + 2);
    const bool closerExpected = detail.find("expected '}'") != std::string::npos ||
                                detail.find("expected ']'") != std::string::npos;
    const bool valueFound = detail.find("unexpected string") != std::string::npos ||
                            detail.find("unexpected number") != std::string::npos ||
                            detail.find("unexpected '{'") != std::string::npos ||
                            detail.find("unexpected '['") != std::string::npos;
    if (closerExpected && valueFound) detail += " (a missing comma before it?)";
    // nlohmann quotes the bytes it read, and these are not text: point at the byte and say what happened.
    if (detail.find("ill-formed UTF-8") != std::string::npos) {
      detail = "a byte that is not UTF-8 (the file was saved in another encoding, such as Latin-1: save it as UTF-8)";
      if (const size_t bad = firstInvalidUtf8(text_, tokenStart); bad != std::string::npos) tokenStart = bad;
    }
    auto [line, col] = lineColumn(text_, tokenStart);
    throwUserError(file_, line, col, "malformed JSON: " + detail);
  }
}

JsonDocument JsonDocument::load(const std::string& path) {
  return JsonDocument(readTextFile(path, "JSON file"), path);
}

std::pair<int, int> JsonDocument::locate(const std::string& pointer) const {
  // Fall back to the nearest recorded ancestor.
  std::string p = pointer;
  for (;;) {
    const auto it = offsets_.find(p);
    if (it != offsets_.end()) return lineColumn(text_, it->second);
    if (p.empty()) return {0, 0};
    p = p.substr(0, p.rfind('/'));
  }
}

void JsonDocument::fail(const std::string& pointer, const std::string& message) const {
  auto [line, col] = locate(pointer);
  throwUserError(file_, line, col, message);
}

// --- JsonNode ----------------------------------------------------------------

namespace {
std::string typeName(const nlohmann::json& j) {
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_boolean()) return "a boolean";
  if (j.is_array()) return "an array";
  if (j.is_object()) return "an object";
  return "null";
}
std::string formatRange(float min, float max) {
  std::ostringstream s;
  s << "[" << min << ", " << max << "]";
  return s.str();
}
}  // namespace

void JsonNode::requireObject() const {
  if (!value_->is_object()) fail(what_ + " must be an object, got " + typeName(*value_));
}

void JsonNode::requireArray() const {
  if (!value_->is_array()) fail(what_ + " must be an array, got " + typeName(*value_));
}

void JsonNode::allowOnly(std::initializer_list<const char*> allowed) const {
  requireObject();
  for (auto it = value_->begin(); it != value_->end(); ++it) {
    if (std::find_if(allowed.begin(), allowed.end(), [&](const char* a) { return it.key() == a; }) ==
        allowed.end())
      doc_->fail(pointer_ + "/" + escapePointerToken(it.key()),
                 "unknown key '" + it.key() + "' in " + what_ + " (allowed: " + joinNames(allowed) + ")");
  }
}

JsonNode JsonNode::child(const std::string& key) const {
  requireObject();
  if (!value_->contains(key)) fail(what_ + " needs the key '" + key + "'");
  return JsonNode(*doc_, (*value_)[key], pointer_ + "/" + escapePointerToken(key),
                  what_.empty() ? key : what_ + "." + key);
}

JsonNode JsonNode::at(size_t index) const {
  requireArray();
  return JsonNode(*doc_, (*value_)[index], pointer_ + "/" + std::to_string(index),
                  what_ + "[" + std::to_string(index) + "]");
}

float JsonNode::asNumber() const {
  if (!value_->is_number()) fail(what_ + " must be a number, got " + typeName(*value_));
  const double v = value_->get<double>();
  // Numbers are floats: beyond +-3.4e38 they would become infinite (and the conversion is undefined).
  if (!(std::abs(v) <= static_cast<double>(std::numeric_limits<float>::max())))
    fail(what_ + " = " + value_->dump() + " is not a finite float (|x| <= 3.4e38)");
  return static_cast<float>(v);
}

Vec3 JsonNode::asVec3() const {
  if (!value_->is_array() || value_->size() != 3)
    fail(what_ + " must be an array of 3 numbers [x, y, z], got " + typeName(*value_) +
         (value_->is_array() ? " of " + std::to_string(value_->size()) : ""));
  return {at(0).asNumber(), at(1).asNumber(), at(2).asNumber()};
}

Vec2 JsonNode::asVec2() const {
  if (!value_->is_array() || value_->size() != 2)
    fail(what_ + " must be an array of 2 numbers [u, v], got " + typeName(*value_));
  return {at(0).asNumber(), at(1).asNumber()};
}

float JsonNode::number(const std::string& key, float min, float max) const {
  const JsonNode n = child(key);
  const float v = n.asNumber();
  if (v < min || v > max) n.fail(n.what_ + " = " + n.value_->dump() + " is out of range " + formatRange(min, max));
  return v;
}

float JsonNode::number(const std::string& key, float fallback, float min, float max) const {
  return has(key) ? number(key, min, max) : fallback;
}

int JsonNode::integer(const std::string& key, int fallback, int min, int max) const {
  if (!has(key)) return fallback;
  const JsonNode n = child(key);
  if (!n.value_->is_number_integer()) n.fail(n.what_ + " must be an integer, got " + n.value_->dump());
  const auto v = n.value_->get<long long>();
  if (v < min || v > max)
    n.fail(n.what_ + " = " + std::to_string(v) + " is out of range [" + std::to_string(min) + ", " +
           std::to_string(max) + "]");
  return static_cast<int>(v);
}

bool JsonNode::boolean(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const JsonNode n = child(key);
  if (!n.value_->is_boolean()) n.fail(n.what_ + " must be true or false, got " + typeName(*n.value_));
  return n.value_->get<bool>();
}

std::string JsonNode::string(const std::string& key) const {
  const JsonNode n = child(key);
  if (!n.value_->is_string()) n.fail(n.what_ + " must be a string, got " + typeName(*n.value_));
  return n.value_->get<std::string>();
}

Vec3 JsonNode::vec3(const std::string& key) const { return child(key).asVec3(); }

Vec3 JsonNode::vec3(const std::string& key, Vec3 fallback) const { return has(key) ? vec3(key) : fallback; }

Rgb JsonNode::color(const std::string& key, Rgb fallback) const {
  if (!has(key)) return fallback;
  const JsonNode n = child(key);
  const Vec3 c = n.asVec3();
  if (minComponent(c) < 0.0f) n.fail(n.what_ + " must have every channel >= 0, got " + n.value_->dump());
  return c;
}

}  // namespace ll
