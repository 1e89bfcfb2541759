// libFuzzer target: the renderer-file reader (renderers/renderer_file.h
// loadRendererFile, a user's xval-renderer/1 definition) on arbitrary
// bytes.
//
// loadRendererFile throws (SceneError, a std::runtime_error) naming the
// file for a definition it cannot use. Findings are crashes, sanitizer
// reports, time-outs, out-of-memory, and any other exception (a library's
// json::exception).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "fuzz_common.h"
#include "renderers/renderer_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path file = xval::fuzz::scratchDir() / "renderer.json";
  xval::fuzz::writeFile(file, data, size);
  try {
    (void)xval::renderers::loadRendererFile(file);
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
