// JsonReader: checked access to one JSON object of a scene file.
//
// Every accessor records the key as known; finish() then rejects any key
// that was never asked for (an unknown field). Every error names the file,
// the field path (e.g. "lights[1].attenuation.linear") and the bad value.
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <optional>
#include <set>
#include <stdexcept>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace xval {

// An error in a scene file; what() is the whole message.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Range constraint for numbers: lo/hi are bounds, open or closed.
struct Range {
  double lo = -1e300, hi = 1e300;
  bool lo_open = false, hi_open = false;
  static Range any() { return {}; }
  static Range nonNegative() { return {0.0, 1e300, false, false}; }
  static Range positive() { return {0.0, 1e300, true, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range openClosed(double a, double b) { return {a, b, true, false}; }
  static Range open(double a, double b) { return {a, b, true, true}; }
  bool contains(double v) const;
  std::string describe() const;
};

class JsonReader {
 public:
  JsonReader(const nlohmann::json& value, std::string path, std::string file);

  const std::string& path() const { return path_; }
  bool has(std::string_view key) const;

  double number(std::string_view key, double fallback, Range r = Range::any());
  double requireNumber(std::string_view key, Range r = Range::any());
  int integer(std::string_view key, int fallback, int lo, int hi);
  glm::dvec3 vec3(std::string_view key, glm::dvec3 fallback, Range r = Range::any());
  glm::dvec3 requireVec3(std::string_view key, Range r = Range::any());
  glm::dvec2 vec2(std::string_view key, glm::dvec2 fallback, Range r = Range::any());
  // A number s, read as (s, s, s), or an array of 3 numbers.
  glm::dvec3 numberOrVec3(std::string_view key, glm::dvec3 fallback, Range r = Range::any());
  std::string string(std::string_view key, std::string fallback);
  std::string requireString(std::string_view key);
  // One of `allowed`; the error lists them.
  std::string choice(std::string_view key, std::string fallback,
                     std::initializer_list<std::string_view> allowed);
  std::string requireChoice(std::string_view key,
                            std::initializer_list<std::string_view> allowed);
  std::string choice(std::string_view key, std::string fallback, std::span<const std::string_view> allowed);
  std::string requireChoice(std::string_view key, std::span<const std::string_view> allowed);
  bool boolean(std::string_view key, bool fallback);
  std::vector<std::string> stringArray(std::string_view key, bool required);
  std::optional<JsonReader> object(std::string_view key);
  JsonReader requireObject(std::string_view key);
  // Elements of an array field, each as a reader (objects only).
  std::vector<JsonReader> objectArray(std::string_view key, bool required);

  // Rejects keys nobody asked for. Call after reading every field.
  void finish() const;

  // Throws a SceneError about `key` of this object.
  [[noreturn]] void fail(std::string_view key, const std::string& problem) const;
  [[noreturn]] void failValue(std::string_view key, const std::string& expected) const;

 private:
  const nlohmann::json* find(std::string_view key);
  std::string fieldPath(std::string_view key) const;
  double toNumber(const nlohmann::json& v, const std::string& where, Range r) const;

  const nlohmann::json& value_;
  std::string path_;
  std::string file_;
  std::set<std::string, std::less<>> known_;
};

// A short, printable rendering of a JSON value for error messages (at most
// 80 characters; never walks more of the value than it prints).
std::string describeJson(const nlohmann::json& v);
std::string describeJson(const nlohmann::ordered_json& v);

// Deepest accepted nesting of arrays and objects (a scene file needs 5).
inline constexpr int kMaxJsonDepth = 64;

// Parses JSON text as a scene or spec file. Beyond the JSON grammar it
// refuses, as a SceneError naming `file`, the field path where the problem
// is, and the offending text: a duplicated key in one object, nesting
// deeper than kMaxJsonDepth, and a number too large for a double (1e400).
// Syntax errors carry the line and column.
nlohmann::json parseJsonText(const std::string& text, const std::string& file);
nlohmann::ordered_json parseOrderedJsonText(const std::string& text, const std::string& file);

}  // namespace xval
