// xval-model-reader: Assimp's read of one model file, in a process of its
// own (geometry/assimp_read.h: why, and what it writes).
//
//   xval-model-reader FILE MAX_FILE_BYTES MAX_TOTAL_BYTES MAX_MEMORY_BYTES
//
// FILE is absolute and canonical; the files Assimp may open are those
// GuardedIO allows in FILE's folder. Outside a sanitizer build the process
// first caps its own address space at MAX_MEMORY_BYTES (RLIMIT_AS), so an
// allocation past it fails (std::bad_alloc, exit 70) instead of taking the
// machine's memory. The output goes to standard output, messages to
// standard error; geometry/model_file.cpp runs it and checks both.
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "geometry/assimp_read.h"

namespace {

bool writeAll(int fd, const char* data, size_t n) {
  while (n > 0) {
    const ssize_t w = write(fd, data, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    data += w, n -= size_t(w);
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path file;
  xval::ModelLimits limits;
  const std::string bad = xval::parseModelReaderArguments(std::vector<std::string>(argv, argv + argc), file, limits);
  if (!bad.empty()) {
    std::cerr << xval::kModelReader << ": " << bad << "\n";
    return 64;
  }
  if (xval::modelReaderCapsMemory() && limits.max_import_memory_bytes > 0) {
    const rlimit cap{rlim_t(limits.max_import_memory_bytes), rlim_t(limits.max_import_memory_bytes)};
    if (setrlimit(RLIMIT_AS, &cap) != 0) {
      std::cerr << xval::kModelReader << ": setrlimit(RLIMIT_AS, " << limits.max_import_memory_bytes
                << "): " << std::strerror(errno) << "\n";
      return 73;
    }
  }
  try {
    const std::string out = xval::readWithAssimp(file, limits);
    if (!writeAll(1, out.data(), out.size())) {
      std::cerr << xval::kModelReader << ": writing the result: " << std::strerror(errno) << "\n";
      return 72;
    }
    // Out without exit-time work: the leak check of a sanitizer build
    // would report Assimp's own (tests/fuzz/assimp_leaks.supp), and
    // nothing is left to flush.
    std::cerr.flush();
    _exit(0);
  } catch (const std::exception& e) {
    std::cerr << "exception: " << e.what() << "\n";
    return 70;
  }
  return 0;
}
