// libFuzzer target: the report's reader of results.json (validate/
// results_shape.h, the check against docs/results-schema.json that every
// report runs first), the typed reader after it (validate/results/
// results.h) and JUnit (validate/report/junit_report.h), on arbitrary bytes.
//
// Every input that the check accepts is also checked with each of its
// fields left out in turn (every member of every object, at any depth):
// the omissions of every field of every seed and of every accepted
// mutation, issue #34.6. Findings are crashes, sanitizer reports,
// time-outs, out-of-memory, and any exception that is not the readers'
// std::runtime_error naming the file (a library's json::exception, a
// logic_error of the schema walk).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/json_reader.h"
#include "validate/report/junit_report.h"
#include "validate/results/results_shape.h"

namespace {

using J = nlohmann::ordered_json;
const std::string kFile = "results.json";

[[noreturn]] void finding(const char* what, const std::string& why) {
  std::fprintf(stderr, "%s: %s\n", what, why.c_str());
  std::abort();
}

// The check, then (when it accepts) JUnit; true when both read it.
bool read(const J& r) {
  try {
    xval::checkResultsShape(r, kFile);
  } catch (const nlohmann::json::exception& e) {
    finding("a library exception from the check", e.what());
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()).rfind(kFile + ": ", 0) != 0) finding("an error not naming the file", e.what());
    return false;
  } catch (const std::exception& e) {
    finding("an unexpected exception from the check", e.what());
  }
  // The typed reader (validate/results/results.h) on what the check
  // accepted, then JUnit on its types.
  try {
    (void)xval::junitXml(xval::results::resultsFromJson(r, kFile), "fuzz");
  } catch (const nlohmann::json::exception& e) {
    finding("a library exception from the typed reader or JUnit on a results.json the check accepted", e.what());
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()).rfind(kFile + ": ", 0) != 0) finding("an error not naming the file", e.what());
  } catch (const std::exception& e) {
    finding("an unexpected exception from the typed reader or JUnit", e.what());
  }
  return true;
}

// Each member of every object below `node`, removed in turn from `root`.
void eachOmission(J& root, J& node) {
  if (node.is_object()) {
    std::vector<std::string> keys;
    for (auto it = node.begin(); it != node.end(); ++it) keys.push_back(it.key());
    for (const std::string& k : keys) {
      J kept = std::move(node[k]);
      node.erase(k);
      read(root);
      node[k] = std::move(kept);  // back, though at the end: order is no part of the format
      eachOmission(root, node[k]);
    }
  } else if (node.is_array()) {
    for (auto& e : node) eachOmission(root, e);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  J r;
  try {
    // As the report reads it (a key twice, nesting deeper than 64: refused).
    r = xval::parseOrderedJsonText(std::string(reinterpret_cast<const char*>(data), size), kFile);
  } catch (const std::runtime_error&) {
    return 0;  // not JSON the report reads: refused before the check
  }
  if (read(r)) eachOmission(r, r);
  return 0;
}
