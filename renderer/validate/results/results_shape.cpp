#include "validate/results/results_shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "validate/results_schema_text.h"  // generated from docs/results-schema.json (renderer/CMakeLists.txt)

namespace xval {

namespace {

using J = nlohmann::ordered_json;
using S = nlohmann::json;  // the schema

const S& schema() {
  static const S s = S::parse(kResultsSchemaText);
  return s;
}

// "#/definitions/case" -> the schema there.
const S& resolve(const S& node) {
  if (!node.is_object() || !node.contains("$ref")) return node;
  const std::string ref = node["$ref"].get<std::string>();
  const std::string prefix = "#/definitions/";
  if (ref.rfind(prefix, 0) != 0) throw std::logic_error("results schema: $ref " + ref + " is not #/definitions/...");
  return resolve(schema()["definitions"].at(ref.substr(prefix.size())));
}

// "a string", "an object", "a number or null".
std::string article(const std::string& type) {
  const std::string word = type == "integer" ? "an integer" : type == "object" ? "an object" : type == "array" ? "an array"
                           : type == "null"  ? "null"
                           : type == "boolean" ? "true or false"
                                               : "a " + type;
  return word;
}

std::string expectedText(const S& node) {
  const S& n = resolve(node);
  if (!n.is_object()) return "a value";
  if (n.contains("const")) return n["const"].dump();
  if (n.contains("enum")) {
    std::string s = "one of";
    for (const auto& v : n["enum"]) s += " " + v.dump();
    return s;
  }
  if (!n.contains("type")) return "a value";
  if (n["type"].is_string()) return article(n["type"].get<std::string>());
  std::string s;
  for (const auto& t : n["type"]) s += (s.empty() ? "" : " or ") + article(t.get<std::string>());
  return s;
}

S asSchemaValue(const J& v) { return S::parse(v.dump(-1, ' ', false, J::error_handler_t::replace)); }

bool hasType(const J& v, const std::string& type) {
  if (type == "object") return v.is_object();
  if (type == "array") return v.is_array();
  if (type == "string") return v.is_string();
  if (type == "number") return v.is_number();
  if (type == "integer")
    return v.is_number_integer() || (v.is_number_float() && std::isfinite(v.get<double>()) &&
                                     std::trunc(v.get<double>()) == v.get<double>());
  if (type == "boolean") return v.is_boolean();
  if (type == "null") return v.is_null();
  throw std::logic_error("results schema: unknown type " + type);
}

// The value as the message quotes it: short.
std::string quoted(const J& v) {
  std::string s = v.dump(-1, ' ', false, J::error_handler_t::replace);
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

struct Checker {
  const std::string& file;

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw std::runtime_error(file + ": " + (where.empty() ? std::string("(the top level)") : where) + ": " + what);
  }

  static std::string member(const std::string& where, const std::string& key) {
    return where.empty() ? key : where + "." + key;
  }

  // Whether `v` matches `node`, without saying why (an `if`).
  bool matches(const J& v, const S& node, const std::string& where) const {
    try {
      check(v, node, where);
      return true;
    } catch (const std::runtime_error&) {
      return false;
    }
  }

  void check(const J& v, const S& node_in, const std::string& where) const {
    const S& node = resolve(node_in);
    if (node.is_boolean()) {
      if (!node.get<bool>()) fail(where, quoted(v) + ": not allowed here");
      return;
    }
    if (node.contains("type")) {
      bool ok = false;
      if (node["type"].is_string()) ok = hasType(v, node["type"].get<std::string>());
      else
        for (const auto& t : node["type"]) ok = ok || hasType(v, t.get<std::string>());
      if (!ok) fail(where, quoted(v) + ": expected " + expectedText(node));
    }
    if (node.contains("const") && asSchemaValue(v) != node["const"]) fail(where, quoted(v) + ": expected " + expectedText(node));
    if (node.contains("enum")) {
      const S sv = asSchemaValue(v);
      if (std::find(node["enum"].begin(), node["enum"].end(), sv) == node["enum"].end())
        fail(where, quoted(v) + ": expected " + expectedText(node));
    }
    if (v.is_number()) {
      if (node.contains("minimum") && v.get<double>() < node["minimum"].get<double>())
        fail(where, quoted(v) + ": expected at least " + node["minimum"].dump());
      if (node.contains("maximum") && v.get<double>() > node["maximum"].get<double>())
        fail(where, quoted(v) + ": expected at most " + node["maximum"].dump());
    }
    if (v.is_object()) checkObject(v, node, where);
    if (v.is_array()) {
      if (node.contains("minItems") && v.size() < node["minItems"].get<size_t>())
        fail(where, std::to_string(v.size()) + " entries: expected at least " + node["minItems"].dump());
      if (node.contains("maxItems") && v.size() > node["maxItems"].get<size_t>())
        fail(where, std::to_string(v.size()) + " entries: expected at most " + node["maxItems"].dump());
      if (node.contains("items"))
        for (size_t i = 0; i < v.size(); ++i) check(v[i], node["items"], where + "[" + std::to_string(i) + "]");
    }
    if (node.contains("if")) {
      if (matches(v, node["if"], where)) {
        if (node.contains("then")) check(v, node["then"], where);
      } else if (node.contains("else")) {
        check(v, node["else"], where);
      }
    }
  }

  void checkObject(const J& v, const S& node, const std::string& where) const {
    const S no_properties = S::object();
    const S& props = node.contains("properties") ? node["properties"] : no_properties;
    if (node.contains("required"))
      for (const auto& k : node["required"]) {
        const std::string key = k.get<std::string>();
        if (!v.contains(key))
          fail(member(where, key),
               "missing (expected " + (props.contains(key) ? expectedText(props[key]) : std::string("a value")) + ")");
      }
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string at = member(where, it.key());
      if (node.contains("propertyNames")) check(J(it.key()), node["propertyNames"], at + " (the name)");
      if (props.contains(it.key())) check(it.value(), props[it.key()], at);
      else if (node.contains("additionalProperties")) {
        const S& extra = node["additionalProperties"];
        if (extra.is_boolean() && !extra.get<bool>())
          fail(at, "not a field here (docs/results-schema.json)");
        check(it.value(), extra, at);
      }
    }
  }
};

}  // namespace

void checkResultsShape(const nlohmann::ordered_json& results, const std::string& file) {
  Checker{file}.check(results, schema(), "");
}

}  // namespace xval
