// libFuzzer target: the scene loader on arbitrary bytes.
//
// Findings are crashes, sanitizer reports, time-outs, and any exception
// other than SceneError (an error without the file/field context). A scene
// that loads must also survive the writer: parseScene(sceneToJson(s))
// gives the same scene (checked through its JSON text).
//
// The scene "file" is in an empty temporary folder: relative texture paths
// resolve to nothing; an absolute path to an existing image is opened
// read-only (its header is checked), as the loader always does.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_common.h"
#include "scene_file/scene_loader.h"
#include "scene_file/scene_writer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path file = xval::fuzz::emptyDir() / "fuzz.json";
  const std::string text(reinterpret_cast<const char*>(data), size);
  xval::Scene scene;
  try {
    scene = xval::parseScene(text, file);
  } catch (const xval::SceneError&) {
    return 0;  // a reported error: the expected outcome for most inputs
  }
  const std::string written = xval::sceneToJson(scene).dump();
  xval::Scene again;
  try {
    again = xval::parseScene(written, file);
  } catch (const xval::SceneError& e) {
    std::fprintf(stderr, "a loaded scene, written back, does not load: %s\n%s\n", e.what(),
                 written.c_str());
    std::abort();
  }
  if (xval::sceneToJson(again).dump() != written) {
    std::fprintf(stderr, "write/read round trip changed the scene:\n%s\n", written.c_str());
    std::abort();
  }
  return 0;
}
