// Provenance of a results file (validate/common/provenance.h).
#include "image/exr_file.h"
#include "image/png_file.h"
#include "validate/common/provenance.h"

#include <ctime>
#include <fstream>
#include <thread>
#include <vector>


#include "process/run_process.h"

namespace xval {

namespace fs = std::filesystem;

namespace {

std::string cpuModel() {
  std::ifstream f("/proc/cpuinfo");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("model name", 0) == 0) {
      const auto c = line.find(':');
      const auto start = c == std::string::npos ? c : line.find_first_not_of(" \t", c + 1);
      if (start != std::string::npos) return line.substr(start);
    }
  return "unknown CPU";
}

std::string utcNow() {
  const std::time_t t = std::time(nullptr);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return b;
}

std::vector<std::string> linesOf(const fs::path& f) {
  std::ifstream in(f);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

}  // namespace

std::string compilerDescription() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("g++ ") + __VERSION__;
#else
  return "unknown compiler";
#endif
}

double loadAverage1() {
  std::ifstream f("/proc/loadavg");
  double l = -1;
  if (!(f >> l)) return -1;
  return l;
}

Provenance collectProvenance(const fs::path& scratch) {
  Provenance p;
  p.date_utc = utcNow();
  p.cpu = cpuModel();
  p.hardware_threads = std::thread::hardware_concurrency();
  p.load_average_1min = loadAverage1();
  p.compiler = compilerDescription();
  p.openexr = openexrVersion();
  p.libpng = libpngVersion();
  p.openimageio = XVAL_OIIO_MODULE_VERSION;
  std::error_code ec;
  const fs::path exe_dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  for (const auto& where : {fs::current_path(), exe_dir}) {
    if (where.empty()) continue;
    ProcessResult r = runProcess({"git", "-C", where.string(), "rev-parse", "HEAD"}, where, scratch, 30);
    if (!r.ok()) continue;
    const auto head = linesOf(scratch);
    if (head.empty()) continue;
    p.git_commit = head.front();
    r = runProcess({"git", "-C", where.string(), "status", "--porcelain", "--untracked-files=no", "--",
                    ":(top,exclude)results"},
                   where, scratch, 30);
    if (r.ok()) p.git_modified_files = long(linesOf(scratch).size());
    if (p.git_modified_files != 0) p.git_commit += "-dirty";
    break;
  }
  fs::remove(scratch, ec);
  return p;
}

}  // namespace xval
