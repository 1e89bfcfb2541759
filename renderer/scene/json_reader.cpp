#include "scene/json_reader.h"

#include <cmath>
#include <sstream>

namespace xval {

using nlohmann::json;

bool Range::contains(double v) const {
  bool lo_ok = lo_open ? v > lo : v >= lo;
  bool hi_ok = hi_open ? v < hi : v <= hi;
  return lo_ok && hi_ok;
}

std::string Range::describe() const {
  std::ostringstream s;
  s.precision(10);
  bool has_lo = lo > -1e300, has_hi = hi < 1e300;
  if (has_lo && has_hi) {
    s << "a number in " << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
  } else if (has_lo) {
    s << "a number " << (lo_open ? "> " : ">= ") << lo;
  } else if (has_hi) {
    s << "a number " << (hi_open ? "< " : "<= ") << hi;
  } else {
    s << "a finite number";
  }
  return s.str();
}

std::string describeJson(const json& v) {
  std::string s = v.dump();
  if (s.size() > 80) s = s.substr(0, 77) + "...";
  return s;
}

JsonReader::JsonReader(const json& value, std::string path, std::string file)
    : value_(value), path_(std::move(path)), file_(std::move(file)) {
  if (!value_.is_object()) {
    throw SceneError(file_ + ": " + (path_.empty() ? "(top level)" : path_) +
                     ": expected a JSON object, got " + describeJson(value_));
  }
}

bool JsonReader::has(std::string_view key) const {
  return value_.find(std::string(key)) != value_.end();
}

std::string JsonReader::fieldPath(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void JsonReader::fail(std::string_view key, const std::string& problem) const {
  throw SceneError(file_ + ": " + fieldPath(key) + ": " + problem);
}

void JsonReader::failValue(std::string_view key, const std::string& expected) const {
  auto it = value_.find(std::string(key));
  std::string got = it == value_.end() ? "nothing" : describeJson(*it);
  fail(key, "expected " + expected + ", got " + got);
}

const json* JsonReader::find(std::string_view key) {
  known_.emplace(key);
  auto it = value_.find(std::string(key));
  return it == value_.end() ? nullptr : &*it;
}

double JsonReader::toNumber(const json& v, const std::string& where, Range r) const {
  if (!v.is_number()) {
    throw SceneError(file_ + ": " + where + ": expected " + r.describe() + ", got " +
                     describeJson(v));
  }
  double d = v.get<double>();
  if (!std::isfinite(d) || !r.contains(d)) {
    std::ostringstream s;
    s.precision(17);
    s << d;
    throw SceneError(file_ + ": " + where + ": expected " + r.describe() + ", got " +
                     (std::isfinite(d) ? describeJson(v) : s.str()));
  }
  return d;
}

double JsonReader::number(std::string_view key, double fallback, Range r) {
  const json* v = find(key);
  return v ? toNumber(*v, fieldPath(key), r) : fallback;
}

double JsonReader::requireNumber(std::string_view key, Range r) {
  const json* v = find(key);
  if (!v) fail(key, "required field is missing (expected " + r.describe() + ")");
  return toNumber(*v, fieldPath(key), r);
}

int JsonReader::integer(std::string_view key, int fallback, int lo, int hi) {
  const json* v = find(key);
  if (!v) return fallback;
  std::string expected =
      "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!v->is_number_integer() && !v->is_number_unsigned()) {
    // 3.0 is accepted as 3; 3.5 is not.
    if (v->is_number_float()) {
      double d = v->get<double>();
      if (std::isfinite(d) && d == std::floor(d) && d >= lo && d <= hi) return int(d);
    }
    failValue(key, expected);
  }
  long long i = v->is_number_unsigned() ? (long long)std::min<unsigned long long>(
                                              v->get<unsigned long long>(), 1ull << 62)
                                        : v->get<long long>();
  if (i < lo || i > hi) failValue(key, expected);
  return int(i);
}

glm::dvec3 JsonReader::vec3(std::string_view key, glm::dvec3 fallback, Range r) {
  const json* v = find(key);
  if (!v) return fallback;
  if (!v->is_array() || v->size() != 3) failValue(key, "an array of 3 numbers");
  glm::dvec3 out;
  for (int i = 0; i < 3; ++i)
    out[i] = toNumber((*v)[i], fieldPath(key) + "[" + std::to_string(i) + "]", r);
  return out;
}

glm::dvec3 JsonReader::requireVec3(std::string_view key, Range r) {
  if (!has(key)) {
    find(key);
    fail(key, "required field is missing (expected an array of 3 numbers)");
  }
  return vec3(key, {}, r);
}

glm::dvec2 JsonReader::vec2(std::string_view key, glm::dvec2 fallback, Range r) {
  const json* v = find(key);
  if (!v) return fallback;
  if (!v->is_array() || v->size() != 2) failValue(key, "an array of 2 numbers");
  glm::dvec2 out;
  for (int i = 0; i < 2; ++i)
    out[i] = toNumber((*v)[i], fieldPath(key) + "[" + std::to_string(i) + "]", r);
  return out;
}

std::string JsonReader::string(std::string_view key, std::string fallback) {
  const json* v = find(key);
  if (!v) return fallback;
  if (!v->is_string()) failValue(key, "a string");
  return v->get<std::string>();
}

std::string JsonReader::requireString(std::string_view key) {
  if (!has(key)) {
    find(key);
    fail(key, "required field is missing (expected a string)");
  }
  return string(key, "");
}

static std::string listChoices(std::initializer_list<std::string_view> allowed) {
  std::string s = "one of";
  bool first = true;
  for (auto a : allowed) {
    s += first ? " \"" : ", \"";
    s += a;
    s += "\"";
    first = false;
  }
  return s;
}

std::string JsonReader::choice(std::string_view key, std::string fallback,
                               std::initializer_list<std::string_view> allowed) {
  const json* v = find(key);
  if (!v) return fallback;
  if (v->is_string()) {
    std::string s = v->get<std::string>();
    for (auto a : allowed)
      if (s == a) return s;
  }
  failValue(key, listChoices(allowed));
}

std::string JsonReader::requireChoice(std::string_view key,
                                      std::initializer_list<std::string_view> allowed) {
  if (!has(key)) {
    find(key);
    fail(key, "required field is missing (expected " + listChoices(allowed) + ")");
  }
  return choice(key, "", allowed);
}

bool JsonReader::boolean(std::string_view key, bool fallback) {
  const json* v = find(key);
  if (!v) return fallback;
  if (!v->is_boolean()) failValue(key, "true or false");
  return v->get<bool>();
}

std::vector<std::string> JsonReader::stringArray(std::string_view key, bool required) {
  const json* v = find(key);
  std::vector<std::string> out;
  if (!v) {
    if (required) fail(key, "required field is missing (expected an array of strings)");
    return out;
  }
  if (!v->is_array()) failValue(key, "an array of strings");
  for (size_t i = 0; i < v->size(); ++i) {
    if (!(*v)[i].is_string())
      throw SceneError(file_ + ": " + fieldPath(key) + "[" + std::to_string(i) +
                       "]: expected a string, got " + describeJson((*v)[i]));
    out.push_back((*v)[i].get<std::string>());
  }
  return out;
}

std::optional<JsonReader> JsonReader::object(std::string_view key) {
  const json* v = find(key);
  if (!v) return std::nullopt;
  if (!v->is_object()) failValue(key, "a JSON object");
  return JsonReader(*v, fieldPath(key), file_);
}

JsonReader JsonReader::requireObject(std::string_view key) {
  auto r = object(key);
  if (!r) fail(key, "required field is missing (expected a JSON object)");
  return *r;
}

std::vector<JsonReader> JsonReader::objectArray(std::string_view key, bool required) {
  const json* v = find(key);
  std::vector<JsonReader> out;
  if (!v) {
    if (required) fail(key, "required field is missing (expected an array of objects)");
    return out;
  }
  if (!v->is_array()) failValue(key, "an array of objects");
  for (size_t i = 0; i < v->size(); ++i)
    out.emplace_back((*v)[i], fieldPath(key) + "[" + std::to_string(i) + "]", file_);
  return out;
}

void JsonReader::finish() const {
  for (auto it = value_.begin(); it != value_.end(); ++it) {
    if (known_.find(it.key()) == known_.end()) {
      std::string known_list;
      for (const auto& k : known_) known_list += (known_list.empty() ? "" : ", ") + k;
      fail(it.key(), "unknown field (value " + describeJson(it.value()) +
                         "); known fields here: " + known_list);
    }
  }
}

}  // namespace xval
