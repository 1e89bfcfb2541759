// Scratch folders and file contents for the unit tests.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace xval::test {

// Every scratch folder this process made; removed when the process exits.
class ScratchFolders {
 public:
  static ScratchFolders& instance() {
    static ScratchFolders folders;
    return folders;
  }
  void add(const std::filesystem::path& d) {
    std::lock_guard<std::mutex> lock(mutex_);
    made_.push_back(d);
  }
  ~ScratchFolders() {
    std::error_code ec;
    for (const auto& d : made_) std::filesystem::remove_all(d, ec);
  }

 private:
  std::mutex mutex_;
  std::vector<std::filesystem::path> made_;
};

// A new, empty folder temp_directory_path()/<leaf>_<pid>_<n>, owned by this process alone.
// CTest runs each gtest case as its own process, two at a time in CI, so a folder named by
// `leaf` alone was shared by the cases of one file: one case's SetUp removed the files
// another was reading (SceneObjects.SceneWriterRoundTripsObjects failed that way).
inline std::filesystem::path freshTempDir(const std::string& leaf) {
  static std::mutex mutex;
  static unsigned next = 0;
  std::lock_guard<std::mutex> lock(mutex);
  for (;;) {
    const std::filesystem::path d = std::filesystem::temp_directory_path() /
                                    (leaf + "_" + std::to_string(::getpid()) + "_" + std::to_string(next++));
    // create_directory is false when the folder exists: a leftover of a process with our pid.
    if (std::filesystem::create_directories(d.parent_path()), std::filesystem::create_directory(d)) {
      ScratchFolders::instance().add(d);
      return d;
    }
  }
}

// The whole file as text ("" when it cannot be read).
inline std::string fileText(const std::filesystem::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace xval::test
