#include "povray/pov_render.h"

#include <cstdio>
#include <fstream>
#include <string>

#include "process/run_process.h"
#include "povray/pov_exporter.h"

namespace xval {

namespace {
// POV-Ray 3.7's statistics end with
//   "  Trace Time:       0 hours  0 minutes  0 seconds (0.665 seconds)";
// the figure in brackets is the trace alone (parsing is reported apart).
double traceTimeFromLog(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line;
  double found = -1.0;
  while (std::getline(in, line)) {
    const auto at = line.find("Trace Time:");
    const auto open = line.rfind('(');
    double s;
    if (at != std::string::npos && open != std::string::npos &&
        std::sscanf(line.c_str() + open, "(%lf seconds)", &s) == 1)
      found = s;
  }
  return found;
}
}  // namespace

Image renderWithPovray(const Scene& scene, const std::filesystem::path& work_dir,
                       double timeout_seconds, ExternalRenderInfo* info, const ExportThrough& through) {
  exportThrough(through, work_dir, [&](const std::filesystem::path& dir) { exportPov(scene, dir); });
  const PovExport ex{work_dir / "scene.pov", work_dir / "scene.ini", work_dir,
                 // The image's name is this attempt's own (+O on the command
                 // line overrides the ini's): a POV-Ray left from an earlier
                 // attempt cannot supply it.
                 "povray-" + attemptToken() + ".png", subpixelGrid(scene)};
  const std::filesystem::path out = work_dir / ex.output_name;
  const std::filesystem::path log = work_dir / "povray.log";
  ProcessResult r = runProcess({"povray", "scene.ini", "+O" + ex.output_name}, work_dir, log, timeout_seconds);
  if (info) *info = {r.seconds, log, traceTimeFromLog(log)};
  requireToolOutput("povray", ex.pov, r, out);
  const SubpixelGrid& g = ex.grid;
  Image fine;
  try {
    // Its header must claim the requested size before any pixel is allocated.
    fine = readImage(out, g.width, g.height);
  } catch (const std::exception& e) {
    throw ExternalToolError(std::string("povray wrote an unusable image: ") + e.what());
  }
  requireImageSize("povray", fine, g.width, g.height);
  requireFinite("povray", fine);
  // Background: alpha 0, colour 0 (as the reference renderer's).
  for (size_t i = 0; i < fine.rgba.size(); i += 4)
    if (fine.rgba[i + 3] == 0.0f) fine.rgba[i] = fine.rgba[i + 1] = fine.rgba[i + 2] = 0.0f;
  // The PNG holds every sample clipped to [0, 1] (the per-sample saturate);
  // n x n blocks to pixels.
  Image img = boxFilter(fine, g.n);
  return img;
}

}  // namespace xval
