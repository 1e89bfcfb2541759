// povray: POV-Ray 3.7, run as an outside tool (povray/pov_render.h).
//
// The scene is exported as SDL that renders, in one render, the reference
// renderer's image (povray/pov_exporter.h, docs/povray-export.md); a scene
// it cannot express exactly is refused with the exporter's reason, never
// approximated. `povray scene.ini` runs in the work folder with a time-out
// (process/run_process.h); its 16-bit PNG is read back as linear values,
// alpha = hit mask.
//
// Parameters (RenderRequest):
//   work_dir         the export (scene.pov, scene.ini, texture.png), the
//                    log (povray.log) and the raw image
//   timeout_seconds  default kDefaultToolTimeoutSeconds (600)
//   exported         the work folder holds the export already (exporter
//                    "pov": exportPov's files), else it is written there
// Needs `povray` on PATH; version: the "POV-Ray ..." line of
// `povray --version`. render_seconds: the log's Trace Time.
#include "povray/pov_exporter.h"
#include "povray/pov_render.h"
#include "renderers/export_cache.h"
#include "renderers/renderer.h"

namespace xval::renderers {

Renderer povrayRenderer() {
  Renderer r;
  r.id = "povray";
  r.display_name = "POV-Ray";
  // Mostly waiting: a 32x32 scene of the throughput sweep takes 1.1 s of
  // wall time and 0.03 s of CPU (/usr/bin/time povray scene.ini); the
  // Table 2 knot's trace keeps two threads busy for 0.45 s of a 1.6 s
  // process. A quarter of a core: four jobs per core.
  r.cpu_share = 0.25;
  // Its start-up and parse, then tracing (validate/validation/job_cost.h).
  r.job_cost = {1.0, 6.0, 25.0};
  // docs/precision-models.md, POV-Ray.
  r.precision = {1.0, 1.0, std::ldexp(1.0, -10), 2e-6, 0.5,
                 "float32 triangle planes, vertices and normals, double weights, float colours; 16-bit PNG"};
  r.summary = "POV-Ray 3.7: the scene exported as SDL, rendered by `povray` with a time-out";
  r.version_command = {"povray", "--version"};
  r.version_marker = "POV-Ray";
  r.exporter =
      RendererExport{"pov", {}, [](const Scene& scene, const std::filesystem::path& dir) { exportPov(scene, dir); }, ""};
  r.cannot_express = [ex = *r.exporter](const Scene& scene) { return refusalOf(ex, scene); };
  r.render = [name = r.exporter->name, id = r.id](const Scene& scene, const RenderRequest& request, RenderInfo* info) {
    ExternalRenderInfo tool;
    Image image = renderWithPovray(id, scene, request.work_dir, request.timeout_seconds, &tool,
                                   request.exported ? exportedAlready() : cachedExport(name, request.export_key));
    setInfo(info, tool);
    return image;
  };
  return r;
}

}  // namespace xval::renderers
