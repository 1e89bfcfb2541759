#include "povray/pov_render.h"

#include <string>

#include "process/run_process.h"
#include "povray/pov_exporter.h"
#include "povray/pov_log.h"

namespace xval {

Image renderWithPovray(const std::string& renderer, const Scene& scene, const std::filesystem::path& work_dir,
                       double timeout_seconds, ExternalRenderInfo* info, const ExportThrough& through,
                       PovTier tier) {
  exportThrough(through, work_dir,
                [&](const std::filesystem::path& dir) { exportPov(scene, dir, "scene.png", tier); });
  const PovExport ex{work_dir / "scene.pov", work_dir / "scene.ini", work_dir,
                 // The image's name is this attempt's own (+O on the command
                 // line overrides the ini's): a POV-Ray left from an earlier
                 // attempt cannot supply it.
                 "povray-" + attemptToken() + ".png", subpixelGrid(scene)};
  const std::filesystem::path out = work_dir / ex.output_name;
  const std::filesystem::path log = work_dir / "povray.log";
  ProcessResult r = runProcess({"povray", "scene.ini", "+O" + ex.output_name}, work_dir, log, timeout_seconds);
  if (info) {
    // parse_seconds: the scene's preparation before the trace, Parse Time
    // plus Bounding Time (the exports use no photons or radiosity).
    const PovLogTimes t = povLogTimesOfFile(log);
    const double prep = t.parse_seconds < 0    ? -1.0
                        : t.bounding_seconds < 0 ? t.parse_seconds
                                                 : t.parse_seconds + t.bounding_seconds;
    *info = {r.seconds, log, t.trace_seconds, prep};
  }
  requireToolOutput(renderer, ex.pov, r, out);
  const SubpixelGrid& g = ex.grid;
  Image fine;
  try {
    // Its header must claim the requested size before any pixel is allocated.
    fine = readImage(out, g.width, g.height);
  } catch (const std::exception& e) {
    throw ExternalToolError(renderer + " wrote an unusable image: " + e.what());
  }
  requireImageSize(renderer, fine, g.width, g.height);
  requireFinite(renderer, fine);
  // Background: alpha 0, colour 0 (as the reference renderer's).
  for (size_t i = 0; i < fine.rgba.size(); i += 4)
    if (fine.rgba[i + 3] == 0.0f) fine.rgba[i] = fine.rgba[i + 1] = fine.rgba[i + 2] = 0.0f;
  // The PNG holds every sample clipped to [0, 1] (the per-sample saturate);
  // n x n blocks to pixels.
  Image img = boxFilter(fine, g.n);
  return img;
}

}  // namespace xval
