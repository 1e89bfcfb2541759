// libFuzzer target: the renderer-file reader (renderers/renderer_file.h
// loadRendererFile, a user's xval-renderer/1 definition) on arbitrary
// bytes.
//
// loadRendererFile throws (SceneError, a std::runtime_error) naming the
// file for a definition it cannot use. Findings are crashes, sanitizer
// reports, time-outs, out-of-memory, and any other exception (a library's
// json::exception).
#include <cstdint>

#include "fuzz_common.h"
#include "renderers/renderer_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path file = xval::fuzz::scratchDir() / "renderer.json";
  xval::fuzz::writeFile(file, data, size);
  xval::fuzz::requireErrorNamingFile(file, [&] { (void)xval::renderers::loadRendererFile(file); });
  return 0;
}
