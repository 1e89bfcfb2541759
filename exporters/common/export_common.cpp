#include "common/export_common.h"

#include <cmath>
#include <cstdio>

namespace xval {

MaterialSlots materialSlots(const Scene& scene) {
  MaterialSlots s;
  s.materials.push_back(&scene.material);
  s.used.push_back(false);
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const auto& own = scene.objects[k].material;
    s.materials.push_back(own ? &*own : nullptr);
    s.used.push_back(own.has_value());
    s.object_slot.push_back(own ? k + 1 : 0);
    if (!own) s.used[0] = true;
  }
  return s;
}

std::string exportedTextureName(size_t slot) {
  return slot == 0 ? "texture.png" : "texture_object" + std::to_string(slot - 1) + ".png";
}

std::optional<Texture> exportTexture(const Material& material, const std::filesystem::path& dir,
                                     const std::string& file, const std::string& what) {
  if (!material.texture) return std::nullopt;
  Texture t = loadTexture(*material.texture);
  if (t.rgb8.empty() && t.rgb16.empty())
    throw ExportError(what + ": texture " + material.texture->path.string() +
                      " is neither 8-bit nor 16-bit integer; the exporters copy textures losslessly "
                      "as 8-bit or 16-bit PNG");
  writeTexturePng(t, dir / file);
  return t;
}

void refuseTrilinear(const Scene& scene, const std::string& exporter, const std::string& why) {
  auto check = [&](const Material& m, const std::string& field) {
    if (m.texture && m.texture->filter == TextureFilter::Trilinear)
      throw ExportError(exporter + ": " + field + ".texture.filter \"trilinear\" is not expressible: " + why);
  };
  check(scene.material, "material");
  for (size_t k = 0; k < scene.objects.size(); ++k)
    if (scene.objects[k].material) check(*scene.objects[k].material, "objects[" + std::to_string(k) + "].material");
}

void refuseUnnormalizedNormal(const Scene& scene, const std::string& exporter, const std::string& why) {
  if (!scene.normalize_normal)
    throw ExportError(exporter + ": normalize_normal false is not expressible: " + why);
}

std::optional<Texture> exportTexture(const Scene& scene, const std::filesystem::path& dir) {
  return exportTexture(scene.material, dir, exportedTextureName(0), "material");
}

void requireToolOutput(const std::string& tool, const std::filesystem::path& input,
                       const ProcessResult& r, const std::filesystem::path& output) {
  const std::string tail = "\nlast lines of " + r.log.string() + ":\n" + tailOfFile(r.log);
  if (!r.ok()) throw ExternalToolError(tool + " (" + input.string() + "): " + r.describe() + tail);
  if (!std::filesystem::exists(output))
    throw ExternalToolError(tool + " (" + input.string() + ") exited 0 but wrote no image " +
                            output.string() + tail);
}

void requireFinite(const std::string& tool, const Image& img) {
  const size_t n = size_t(img.width) * size_t(img.height);
  const bool raw = img.raw.size() == n * 3;
  size_t bad = 0, first = 0;
  for (size_t i = 0; i < n; ++i) {
    bool finite = true;
    for (int c = 0; c < 4; ++c) finite &= std::isfinite(img.rgba[i * 4 + c]);
    if (raw)
      for (int c = 0; c < 3; ++c) finite &= std::isfinite(img.raw[i * 3 + c]);
    if (!finite && bad++ == 0) first = i;
  }
  if (!bad) return;
  char px[160];
  const float* p = &img.rgba[first * 4];
  std::snprintf(px, sizeof px, "R=%g G=%g B=%g A=%g", p[0], p[1], p[2], p[3]);
  throw ExternalToolError(tool + " wrote an image with non-finite values (NaN or infinity) in " +
                          std::to_string(bad) + " of " + std::to_string(n) + " pixels, the first at x=" +
                          std::to_string(first % size_t(img.width)) + ", y=" +
                          std::to_string(first / size_t(img.width)) + " (" + px +
                          "); a renderer's image must be finite");
}

void requireImageSize(const std::string& tool, const Image& img, int width, int height) {
  if (img.width != width || img.height != height)
    throw ExternalToolError(tool + " wrote a " + std::to_string(img.width) + "x" +
                            std::to_string(img.height) + " image, expected " +
                            std::to_string(width) + "x" + std::to_string(height));
}

}  // namespace xval
