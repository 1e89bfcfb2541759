// libFuzzer target: the pack manifest reader (pack/set_pack.h
// verifyUnpacked, DIR/pack-manifest.json of an unpacked set) on arbitrary
// bytes, in a folder that holds nothing else: every file a well-formed
// manifest names is then reported missing (a line), never read.
//
// verifyUnpacked throws PackError (a std::runtime_error) naming the
// manifest for one it cannot use. Findings are crashes, sanitizer reports,
// time-outs, out-of-memory, and any other exception (a library's
// json::exception).
#include <cstdint>

#include "fuzz_common.h"
#include "pack/set_pack.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path& dir = xval::fuzz::scratchDir();
  const std::filesystem::path file = dir / xval::pack::kManifestName;
  xval::fuzz::writeFile(file, data, size);
  xval::fuzz::requireErrorNamingFile(file, [&] { (void)xval::pack::verifyUnpacked(dir); });
  return 0;
}
