// What the exporters and external-renderer harnesses share: their errors,
// the texture copy, and the checks on a tool's run.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "process/run_process.h"
#include "image/image.h"
#include "scene/scene.h"
#include "texture/texture.h"

namespace xval {

// A scene an exporter cannot express exactly (the message says why).
class ExportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An external renderer is missing, failed, timed out or wrote no image.
class ExternalToolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ExternalRenderInfo {
  double seconds = 0.0;          // the tool's whole process, wall time
  std::filesystem::path log;
  double render_seconds = -1.0;  // the render alone, as the tool reports it (-1: not reported)
  double parse_seconds = -1.0;   // reading the scene, as the tool reports it (-1: not reported)
};

inline constexpr double kDefaultToolTimeoutSeconds = 600.0;

// How a render harness gets its export into a folder: through(dir, write)
// leaves in `dir` exactly the files write(dir) writes (it may call write,
// or restore the same files it stored before: renderers/export_cache.h),
// and throws what write throws (ExportError for a refusal). Empty: the
// harness calls write(dir) itself.
using ExportThrough =
    std::function<void(const std::filesystem::path& dir, const std::function<void(const std::filesystem::path&)>& write)>;
// The ExportThrough of a folder that already holds the export (its caller
// wrote it there): nothing is written.
inline ExportThrough exportedAlready() {
  return [](const std::filesystem::path&, const std::function<void(const std::filesystem::path&)>&) {};
}
inline void exportThrough(const ExportThrough& through, const std::filesystem::path& dir,
                          const std::function<void(const std::filesystem::path&)>& write) {
  if (through) through(dir, write);
  else write(dir);
}

// Loads the material's texture and writes it as DIR/texture.png (its 8-bit
// or 16-bit codes, RGB as stored; the exporters never pass the user's path
// on). None without a texture. Throws ExportError for a texture with
// neither (a float image).
std::optional<Texture> exportTexture(const Scene& scene, const std::filesystem::path& dir);

// The materials an export writes, one slot each: slot 0 is the scene's
// material, slot k + 1 object k's own (when it has one). `object_slot[k]`
// is the slot object k is shaded with; `used[s]` whether any object uses
// slot s (an unused slot is not written, its texture not read).
struct MaterialSlots {
  std::vector<const Material*> materials;
  std::vector<size_t> object_slot;
  std::vector<bool> used;
};
MaterialSlots materialSlots(const Scene& scene);

// The name of slot s's texture copy in the export folder: "texture.png"
// for the scene's material (slot 0), "texture_object<k>.png" for object
// k's (slot k + 1). Never a user string.
std::string exportedTextureName(size_t slot);

// Loads `material`'s texture and writes it as DIR/`file` (as exportTexture
// above). None without a texture; throws ExportError naming `what` (e.g.
// "objects[2].material") for a float image.
std::optional<Texture> exportTexture(const Material& material, const std::filesystem::path& dir,
                                     const std::string& file, const std::string& what);

// The paper's listing's own choices (scene.h): throws ExportError, naming
// the field and `why` (the exporter's reason), when some material's texture
// has filter trilinear / when the scene's normalize_normal is false.
void refuseTrilinear(const Scene& scene, const std::string& exporter, const std::string& why);
void refuseUnnormalizedNormal(const Scene& scene, const std::string& exporter, const std::string& why);

// Throws ExternalToolError, with the tail of the log, unless `r` succeeded
// and wrote `output`.
void requireToolOutput(const std::string& tool, const std::filesystem::path& input,
                       const ProcessResult& r, const std::filesystem::path& output);

// Throws ExternalToolError when any channel of any pixel of `img` (colour,
// alpha, and the unsaturated raw colour when present) is NaN or infinite:
// saying which tool, how many pixels, and the first one. Checked before
// anything saturates, which would turn NaN into 0 and +Inf into 1.
void requireFinite(const std::string& tool, const Image& img);

// Throws ExternalToolError unless `img` is width x height (the image the
// tool was asked for: common/supersample.h's grid).
void requireImageSize(const std::string& tool, const Image& img, int width, int height);

}  // namespace xval
