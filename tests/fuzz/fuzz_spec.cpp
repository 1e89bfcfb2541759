// libFuzzer target: the generator's spec parser (xval generate) on
// arbitrary bytes. Every scene a spec generates is validated by the scene
// loader inside generateScenesFromText; here each one must also load again
// from its own JSON text.
//
// Findings are crashes, sanitizer reports, time-outs, out-of-memory, and
// any exception other than SceneError.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_common.h"
#include "scene_file/scene_generator.h"
#include "scene_file/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path spec = xval::fuzz::emptyDir() / "spec.json";
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<xval::GeneratedScene> scenes;
  try {
    scenes = xval::generateScenesFromText(text, spec);
  } catch (const xval::SceneError&) {
    return 0;
  }
  for (const auto& g : scenes) {
    try {
      xval::parseScene(g.json.dump(), xval::fuzz::emptyDir() / (g.name + ".json"));
    } catch (const xval::SceneError& e) {
      std::fprintf(stderr, "generated scene %s does not load: %s\n", g.name.c_str(), e.what());
      std::abort();
    }
  }
  return 0;
}
