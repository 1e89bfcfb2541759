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

namespace {

// dump() that replaces invalid UTF-8 (a path from the command line or the
// file system may hold any bytes) instead of throwing.
template <class BasicJson>
std::string dumpLenient(const BasicJson& v) {
  return v.dump(-1, ' ', false, BasicJson::error_handler_t::replace);
}

// Appends v as compact JSON (as dump() writes it) until `out` is longer
// than `budget`; containers are entered only while there is budget left,
// so neither the depth nor the size of v matters.
template <class BasicJson>
void appendBrief(const BasicJson& v, std::string& out, size_t budget) {
  if (out.size() > budget) return;
  if (v.is_object()) {
    out += '{';
    bool first = true;
    for (auto it = v.begin(); it != v.end() && out.size() <= budget; ++it) {
      if (!first) out += ',';
      first = false;
      out += dumpLenient(BasicJson(it.key()));
      out += ':';
      appendBrief(it.value(), out, budget);
    }
    out += '}';
  } else if (v.is_array()) {
    out += '[';
    bool first = true;
    for (auto it = v.begin(); it != v.end() && out.size() <= budget; ++it) {
      if (!first) out += ',';
      first = false;
      appendBrief(*it, out, budget);
    }
    out += ']';
  } else if (v.is_string()) {
    // A long string is cut before it is escaped (dump() is linear anyway,
    // but a 60 MB string need not be copied for an 80-character message).
    const auto& str = v.template get_ref<const std::string&>();
    std::string head = str.substr(0, budget + 1);
    // Do not cut a UTF-8 sequence in two (dump() would throw on it).
    if (head.size() < str.size())
      while (!head.empty() && (static_cast<unsigned char>(head.back()) & 0xC0) == 0x80) head.pop_back();
    if (head.size() < str.size() && !head.empty() && (static_cast<unsigned char>(head.back()) & 0x80))
      head.pop_back();
    out += dumpLenient(BasicJson(head));
  } else {
    out += v.dump();
  }
}

template <class BasicJson>
std::string describeBrief(const BasicJson& v) {
  std::string s;
  appendBrief(v, s, 80);
  if (s.size() > 80) {
    s.resize(77);
    // Keep the text valid UTF-8: drop a cut multi-byte sequence.
    size_t cut = s.size();
    while (cut > 0 && (static_cast<unsigned char>(s[cut - 1]) & 0xC0) == 0x80) --cut;
    if (cut > 0 && (static_cast<unsigned char>(s[cut - 1]) & 0x80)) s.resize(cut - 1);
    s += "...";
  }
  return s;
}

}  // namespace

std::string describeJson(const json& v) { return describeBrief(v); }
std::string describeJson(const nlohmann::ordered_json& v) { return describeBrief(v); }

namespace {

// Builds the document like nlohmann's own DOM parser, and also knows where
// it is (the field path), so that every error can name the field.
template <class BasicJson>
class CheckedSax {
 public:
  CheckedSax(const std::string& text, const std::string& file) : text_(text), file_(file) {}

  BasicJson result;

  bool null() { put(BasicJson(nullptr)); return true; }
  bool boolean(bool b) { put(BasicJson(b)); return true; }
  bool number_integer(typename BasicJson::number_integer_t i) { put(BasicJson(i)); return true; }
  bool number_unsigned(typename BasicJson::number_unsigned_t u) { put(BasicJson(u)); return true; }
  bool number_float(typename BasicJson::number_float_t d, const std::string&) {
    put(BasicJson(d));
    return true;
  }
  bool string(std::string& s) { put(BasicJson(std::move(s))); return true; }
  bool binary(typename BasicJson::binary_t& b) { put(BasicJson::binary(b)); return true; }

  bool start_object(std::size_t) {
    BasicJson* o = put(BasicJson::object());
    open(o, false);
    return true;
  }
  bool key(std::string& k) {
    Frame& f = stack_.back();
    const bool duplicate = f.value->contains(k);
    f.key = std::move(k);
    if (duplicate)
      fail(path(), "duplicate field " + BasicJson(f.key).dump() +
                       " (a field may appear only once in an object)");
    return true;
  }
  bool end_object() {
    stack_.pop_back();
    return true;
  }
  bool start_array(std::size_t) {
    BasicJson* a = put(BasicJson::array());
    open(a, true);
    return true;
  }
  bool end_array() {
    stack_.pop_back();
    return true;
  }

  template <class Exception>
  bool parse_error(std::size_t position, const std::string& last_token, const Exception& ex) {
    std::string where = lineColumn(position);
    if (ex.id == 406) {
      // The only out_of_range error the parser raises: a number that does
      // not fit a double.
      fail(path(), "number " + last_token + " is too large for a double (" + where +
                       "); expected a finite number");
    }
    std::string what = ex.what();
    fail(path(), what + (what.find("line ") == std::string::npos ? " (" + where + ")" : "") +
                     "; the text there: " + textAt(position));
    return false;  // not reached (fail throws); g++ wants a return here
  }

 private:
  struct Frame {
    BasicJson* value;
    bool is_array;
    std::string key;
  };

  void open(BasicJson* container, bool is_array) {
    if (int(stack_.size()) >= kMaxJsonDepth)
      fail(path(), "arrays and objects nested deeper than " + std::to_string(kMaxJsonDepth) +
                       " levels");
    stack_.push_back({container, is_array, {}});
  }

  BasicJson* put(BasicJson&& v) {
    if (stack_.empty()) {
      result = std::move(v);
      return &result;
    }
    Frame& f = stack_.back();
    if (f.is_array) {
      f.value->push_back(std::move(v));
      return &f.value->back();
    }
    BasicJson& slot = (*f.value)[f.key];
    slot = std::move(v);
    return &slot;
  }

  // The field being read: the current key of each open object, the index
  // of the element being read in each open array.
  std::string path() const {
    std::string p;
    for (size_t i = 0; i < stack_.size(); ++i) {
      const Frame& f = stack_[i];
      const bool inner = i + 1 < stack_.size();  // a child container is open
      if (f.is_array) {
        const size_t n = f.value->size();
        p += "[" + std::to_string(inner ? n - 1 : n) + "]";
      } else if (inner || !f.key.empty()) {
        p += (p.empty() ? "" : ".") + f.key;
      }
    }
    return p;
  }

  std::string lineColumn(std::size_t position) const {
    position = std::min(position, text_.size());
    size_t line = 1, col = 1;
    for (size_t i = 0; i + 1 < position; ++i) {
      if (text_[i] == '\n') ++line, col = 1;
      else ++col;
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(col);
  }

  // Up to 24 bytes of the text from the character the parser stopped at,
  // on one line, as a JSON string (invalid UTF-8 replaced).
  std::string textAt(std::size_t position) const {
    size_t start = std::min(position > 0 ? position - 1 : 0, text_.size());
    std::string s = text_.substr(start, 24);
    s = s.substr(0, s.find('\n'));
    return dumpLenient(BasicJson(s));
  }

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw SceneError(file_ + ": not valid JSON" + (field.empty() ? "" : " in field " + field) +
                     ": " + problem);
  }

  const std::string& text_;
  const std::string& file_;
  std::vector<Frame> stack_;
};

template <class BasicJson>
BasicJson parseChecked(const std::string& text, const std::string& file) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw SceneError(file + ": (top level): the file is empty; expected a JSON object");
  CheckedSax<BasicJson> sax(text, file);
  BasicJson::sax_parse(text, &sax);
  return std::move(sax.result);
}

}  // namespace

json parseJsonText(const std::string& text, const std::string& file) {
  return parseChecked<json>(text, file);
}

nlohmann::ordered_json parseOrderedJsonText(const std::string& text, const std::string& file) {
  return parseChecked<nlohmann::ordered_json>(text, file);
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

glm::dvec3 JsonReader::numberOrVec3(std::string_view key, glm::dvec3 fallback, Range r) {
  const json* v = find(key);
  if (!v) return fallback;
  if (v->is_number()) return glm::dvec3(toNumber(*v, fieldPath(key), r));
  if (!v->is_array() || v->size() != 3) failValue(key, "a number or an array of 3 numbers");
  return vec3(key, fallback, r);
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

static std::string listChoices(std::span<const std::string_view> allowed) {
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
  return choice(key, std::move(fallback), std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

std::string JsonReader::choice(std::string_view key, std::string fallback,
                               std::span<const std::string_view> allowed) {
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
  return requireChoice(key, std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

std::string JsonReader::requireChoice(std::string_view key, std::span<const std::string_view> allowed) {
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
