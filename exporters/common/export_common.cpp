#include "common/export_common.h"

namespace xval {

std::optional<Texture> exportTexture(const Scene& scene, const std::filesystem::path& dir) {
  if (!scene.material.texture) return std::nullopt;
  Texture t = loadTexture(*scene.material.texture);
  if (t.rgb8.empty() && t.rgb16.empty())
    throw ExportError("texture " + scene.material.texture->path.string() +
                      " is neither 8-bit nor 16-bit integer; the exporters copy textures losslessly "
                      "as 8-bit or 16-bit PNG");
  writeTexturePng(t, dir / "texture.png");
  return t;
}

void requireToolOutput(const std::string& tool, const std::filesystem::path& input,
                       const ProcessResult& r, const std::filesystem::path& output) {
  const std::string tail = "\nlast lines of " + r.log.string() + ":\n" + tailOfFile(r.log);
  if (!r.ok()) throw ExternalToolError(tool + " (" + input.string() + "): " + r.describe() + tail);
  if (!std::filesystem::exists(output))
    throw ExternalToolError(tool + " (" + input.string() + ") exited 0 but wrote no image " +
                            output.string() + tail);
}

void requireImageSize(const std::string& tool, const Image& img, const Scene& scene) {
  if (img.width != scene.camera.width || img.height != scene.camera.height)
    throw ExternalToolError(tool + " wrote a " + std::to_string(img.width) + "x" +
                            std::to_string(img.height) + " image, expected " +
                            std::to_string(scene.camera.width) + "x" +
                            std::to_string(scene.camera.height));
}

}  // namespace xval
