// libFuzzer target: the golden-image manifest reader (golden/golden_set.h
// readManifest, DIR/manifest.json of a golden set) on arbitrary bytes.
//
// readManifest throws std::runtime_error naming the file for a manifest it
// cannot use. Findings are crashes, sanitizer reports, time-outs,
// out-of-memory, and any other exception (a library's json::exception).
#include <cstdint>

#include "fuzz_common.h"
#include "golden/golden_set.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path& dir = xval::fuzz::scratchDir();
  const std::filesystem::path file = dir / "manifest.json";
  xval::fuzz::writeFile(file, data, size);
  xval::fuzz::requireErrorNamingFile(file, [&] { (void)xval::golden::readManifest(dir, "reference"); });
  return 0;
}
