// Where and how a results file was made: one record, collected one way,
// for every experiment that writes results (extremes, trade-off, ...).
//
//   date_utc            the time of collection, ISO 8601 in UTC
//                       ("2026-12-01T11:46:44Z"); date() is its first ten
//                       characters;
//   cpu                 "model name" of the first processor in
//                       /proc/cpuinfo, "unknown CPU" when there is none;
//   hardware_threads    std::thread::hardware_concurrency();
//   load_average_1min   the first field of /proc/loadavg, -1 when unknown
//                       (loadAverage1() reads it again, e.g. at the end);
//   git_commit          `git rev-parse HEAD` of the working tree xval runs
//                       in, else of the tree its executable was built in
//                       (build folders live inside the source tree), with
//                       "-dirty" when tracked files outside results/ have
//                       uncommitted changes (the published report there is
//                       rewritten by the run itself); "unknown" when
//                       neither is a git checkout or git is missing;
//   git_modified_files  how many tracked files outside results/ have
//                       uncommitted changes (-1: unknown);
//   compiler            the compiler that built this xval, from its own
//                       predefined macros: "clang <__clang_version__>" or
//                       "g++ <__VERSION__>";
//   openexr, libpng     the versions of the libraries xval reads and writes
//                       EXRs and PNGs with (image/exr_file.h, png_file.h);
//   openimageio         the OpenImageIO version the module xval_oiio was
//                       built against (image/other_formats.h: it decodes
//                       the other formats, loaded only when one is read).
//
// collectProvenance(scratch) runs git (30 s time-out each) with its output
// in the file `scratch`, removed afterwards.
#pragma once

#include <filesystem>
#include <string>

namespace xval {

struct Provenance {
  std::string date_utc;
  std::string cpu = "unknown CPU";
  unsigned hardware_threads = 0;
  double load_average_1min = -1.0;
  std::string git_commit = "unknown";
  long git_modified_files = -1;
  std::string compiler;
  std::string openexr, libpng, openimageio;
  std::string date() const { return date_utc.substr(0, 10); }
};

Provenance collectProvenance(const std::filesystem::path& scratch);

std::string compilerDescription();
double loadAverage1();

}  // namespace xval
