// Shared by the fuzz targets: an empty private folder that scene files
// "live" in, so that relative texture paths resolve to nothing (the
// targets never write into it).
#pragma once

#include <stdlib.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace xval::fuzz {

inline const std::filesystem::path& emptyDir() {
  static const std::filesystem::path dir = [] {
    std::string tmpl = (std::filesystem::temp_directory_path() / "xval_fuzz_XXXXXX").string();
    if (!mkdtemp(tmpl.data())) {
      std::perror("mkdtemp");
      std::abort();
    }
    return std::filesystem::path(tmpl);
  }();
  return dir;
}

}  // namespace xval::fuzz
