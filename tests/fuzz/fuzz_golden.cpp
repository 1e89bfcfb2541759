// libFuzzer target: the golden-image manifest reader (golden/golden_set.h
// readManifest, DIR/manifest.json of a golden set) on arbitrary bytes.
//
// readManifest throws std::runtime_error naming the file for a manifest it
// cannot use. Findings are crashes, sanitizer reports, time-outs,
// out-of-memory, and any other exception (a library's json::exception).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "fuzz_common.h"
#include "golden/golden_set.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path& dir = xval::fuzz::scratchDir();
  const std::filesystem::path file = dir / "manifest.json";
  xval::fuzz::writeFile(file, data, size);
  try {
    (void)xval::readManifest(dir, "reference");
  } catch (const nlohmann::json::exception& e) {
    std::fprintf(stderr, "a library exception: %s\n", e.what());
    std::abort();
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()).find(file.string()) == std::string::npos) {
      std::fprintf(stderr, "an error not naming %s: %s\n", file.c_str(), e.what());
      std::abort();
    }
  }
  return 0;
}
