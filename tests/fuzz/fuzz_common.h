// Shared by the fuzz targets: an empty private folder that scene files
// "live" in, so that relative texture paths resolve to nothing (the
// targets never write into it); and a private scratch folder for the
// targets whose readers take a file (validate's plan and records, the
// tolerance file).
#pragma once

#include <stdlib.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace xval::fuzz {

inline std::filesystem::path makePrivateDir() {
  std::string tmpl = (std::filesystem::temp_directory_path() / "xval_fuzz_XXXXXX").string();
  if (!mkdtemp(tmpl.data())) {
    std::perror("mkdtemp");
    std::abort();
  }
  return std::filesystem::path(tmpl);
}

inline const std::filesystem::path& emptyDir() {
  static const std::filesystem::path dir = makePrivateDir();
  return dir;
}

inline const std::filesystem::path& scratchDir() {
  static const std::filesystem::path dir = makePrivateDir();
  return dir;
}

// Writes the input as the file a reader takes (aborts if it cannot: the
// run would test nothing).
inline void writeFile(const std::filesystem::path& file, const uint8_t* data, size_t size) {
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (!f || std::fwrite(data, 1, size, f) != size || std::fclose(f) != 0) {
    std::perror(file.c_str());
    std::abort();
  }
}

// Runs `read` on `file`: a reader that refuses an input throws a
// std::runtime_error naming the file. Aborts (a finding) on a JSON
// library's exception (a message without the file and field) or an error
// that does not name the file.
template <class Read>
void requireErrorNamingFile(const std::filesystem::path& file, Read read) {
  try {
    read();
  } catch (const nlohmann::json::exception& e) {
    std::fprintf(stderr, "a library exception: %s\n", e.what());
    std::abort();
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()).find(file.string()) == std::string::npos) {
      std::fprintf(stderr, "an error not naming %s: %s\n", file.c_str(), e.what());
      std::abort();
    }
  }
}

}  // namespace xval::fuzz
