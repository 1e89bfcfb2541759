#include "povray/pov_render.h"

#include "common/run_process.h"
#include "povray/pov_exporter.h"

namespace xval {

Image renderWithPovray(const Scene& scene, const std::filesystem::path& work_dir,
                       double timeout_seconds, ExternalRenderInfo* info) {
  PovExport ex = exportPov(scene, work_dir);
  const std::filesystem::path out = work_dir / ex.output_name;
  std::filesystem::remove(out);
  const std::filesystem::path log = work_dir / "povray.log";
  ProcessResult r = runProcess({"povray", "scene.ini"}, work_dir, log, timeout_seconds);
  if (info) *info = {r.seconds, log};
  requireToolOutput("povray", ex.pov, r, out);
  Image img;
  try {
    img = readImage(out);
  } catch (const std::exception& e) {
    throw ExternalToolError(std::string("povray wrote an unreadable image: ") + e.what());
  }
  requireImageSize("povray", img, scene);
  // Background: alpha 0, colour 0 (as the reference renderer's).
  for (size_t i = 0; i < img.rgba.size(); i += 4)
    if (img.rgba[i + 3] == 0.0f) img.rgba[i] = img.rgba[i + 1] = img.rgba[i + 2] = 0.0f;
  return img;
}

}  // namespace xval
