// Scratch folders and file contents for the unit tests.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace xval::test {

// temp_directory_path()/leaf, emptied and created afresh.
inline std::filesystem::path freshTempDir(const std::string& leaf) {
  const std::filesystem::path d = std::filesystem::temp_directory_path() / leaf;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// The whole file as text ("" when it cannot be read).
inline std::string fileText(const std::filesystem::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace xval::test
