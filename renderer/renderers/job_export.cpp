// A job's refusal and export in one (job_export.h).
#include "renderers/job_export.h"

#include "files/sha256.h"
#include "renderers/export_cache.h"
#include "renderers/registry.h"

namespace xval::renderers {

std::string refusalKey(const Renderer& renderer, const std::string& inputs_key) {
  if (inputs_key.empty()) return "";
  // A golden set refuses what the renderer that made it refuses (golden.cpp):
  // that renderer's definition file is part of the key.
  const Renderer* maker = renderer.images_of.empty() ? nullptr : registry().find(renderer.images_of);
  const std::filesystem::path& file = maker ? maker->definition_file : renderer.definition_file;
  const std::string definition = file.empty() ? std::string() : sha256File(file);
  return sha256Pieces([&](const std::function<void(const char*, size_t)>& update) {
    for (const std::string& piece : {inputs_key, renderer.id, definition}) {
      update(piece.data(), piece.size());
      update("\0", 1);
    }
  });
}

std::string refuseOrExport(const Renderer& renderer, const Scene& scene, RenderRequest& request) {
  const std::string key = refusalKey(renderer, request.export_key);
  if (!renderer.exporter) {
    if (!renderer.cannot_express) return "";
    return cachedRefusal(renderer.id, key, [&] { return renderer.cannot_express(scene); });
  }
  const RendererExport& ex = *renderer.exporter;
  const ExportThrough through = cachedExport(ex.name, request.export_key);
  auto write = [&](const std::filesystem::path& dir) { ex.write(scene, dir); };
  const std::filesystem::path dir = ex.folder.empty() ? request.work_dir : request.work_dir / ex.folder;
  bool written = false;
  const std::string why = cachedRefusal(renderer.id, key, [&]() -> std::string {
    try {
      if (ex.check) ex.check(scene);
      exportThrough(through, dir, write);
    } catch (const ExportError& e) {
      return e.what();
    }
    written = true;
    return "";
  });
  if (!why.empty()) return why;
  // The refusal was read back: the export is still to be written.
  if (!written) exportThrough(through, dir, write);
  request.exported = true;
  return "";
}

}  // namespace xval::renderers
