// Helpers of the renderer files (renderer.h).
#include "renderers/renderer.h"

#include "files/scratch_folder.h"
#include "process/run_process.h"

namespace xval::renderers {

std::string exportRefusal(const std::function<void(const std::filesystem::path& dir)>& write_export) {
  namespace fs = std::filesystem;
  const ScratchFolder scratch("export-check");
  const fs::path dir = scratch.dir() / "export";
  fs::create_directory(dir);
  try {
    write_export(dir);
  } catch (const ExportError& e) {
    return e.what();
  }
  return "";
}

std::string refusalOf(const RendererExport& ex, const Scene& scene) {
  if (ex.check) {
    try {
      ex.check(scene);
    } catch (const ExportError& e) {
      return e.what();
    }
  }
  return exportRefusal([&](const std::filesystem::path& dir) { ex.write(scene, dir); });
}

void setInfo(RenderInfo* info, const ExternalRenderInfo& tool) {
  if (!info) return;
  info->seconds = tool.seconds;
  info->render_seconds = tool.render_seconds;
  info->parse_seconds = tool.parse_seconds;
  info->log = tool.log;
}

}  // namespace xval::renderers
