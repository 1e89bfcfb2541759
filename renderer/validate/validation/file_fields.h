// What the plan, the job records and the results file of `xval validate`
// share: reading a file's bytes, the wall-clock time, and field readers
// whose errors name the file and the field (plan.h, job_record.h).
#pragma once

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace xval::validation {

// Seconds since the Unix epoch, now.
inline double nowUnix() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// The file's bytes; throws std::runtime_error naming the file.
inline std::string readBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot read");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Field readers for the plan and records: errors name the file and field.
struct FieldReader {
  using J = nlohmann::ordered_json;
  const std::string file;
  const J& at(const J& obj, const std::string& key, const std::string& where) const {
    if (!obj.is_object() || !obj.contains(key))
      throw std::runtime_error(file + ": " + where + key + ": missing");
    return obj[key];
  }
  std::string str(const J& obj, const std::string& key, const std::string& where = "") const {
    const J& v = at(obj, key, where);
    if (!v.is_string())
      throw std::runtime_error(file + ": " + where + key + ": " + v.dump() + ": expected a string");
    return v.get<std::string>();
  }
  double num(const J& obj, const std::string& key, const std::string& where = "") const {
    const J& v = at(obj, key, where);
    if (!v.is_number())
      throw std::runtime_error(file + ": " + where + key + ": " + v.dump() + ": expected a number");
    return v.get<double>();
  }
};

}  // namespace xval::validation
