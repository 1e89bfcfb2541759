// reference: xval's own renderer (render/renderer.h), the one every other
// renderer is compared against.
//
// A ray caster with the paper's local illumination: no shadows, no
// inter-reflection, each lighting model of shading/models.h evaluated at
// the first hit of each sample. Runs in this process (no outside tool, no
// work folder, no time-out); its version is xval's.
//
// Parameters (RenderRequest::options, a RenderOptions), with the defaults
// used when none are given:
//   precision        double: the exact reference path (double-precision
//                    watertight ray test and shading); float is the fast
//                    path (rasterised or Embree packets)
//   spp              the scene's render.spp (n x n stratified, box filter)
//   threads          0: every hardware thread
//   diagnostics      on: the EXR's raw, Z, backfacing, incidence, albedo,
//                    texel_edge, triangle_edge and the precision probes
//                    (image/image.h kProbeChannels)
//   cull_back_faces  on: back faces of closed meshes seen from outside are
//                    skipped (never a first hit; the image is the same)
//   rasterise        on (float only): rasterise when the whole scene is in
//                    front of the camera
// It expresses every scene the loader accepts.
#include <cmath>
#include <chrono>

#include "renderers/renderer.h"

namespace xval::renderers {

Renderer referenceRenderer() {
  Renderer r;
  r.id = "reference";
  r.job_cost = kReferenceJobCost;
  r.display_name = "reference";
  r.subject = "the reference renderer";
  r.summary = "xval's ray caster (local illumination, no shadows; exact double-precision path)";
  r.reference = true;
  // validate renders it on the double path: hit, uv and normal in double;
  // only the image's float32 storage rounds (docs/precision-models.md).
  r.precision = {0.0, 0.0, 0.0, std::ldexp(1.0, -24), 0.0, "double hit, uv, normal and shading; float32 image"};
  r.render = [](const Scene& scene, const RenderRequest& request, RenderInfo* info) {
    RenderOptions options = request.options ? *request.options : defaultOptions(scene);
    if (!request.options) options.precision = Precision::Double;
    const auto t0 = std::chrono::steady_clock::now();
    RenderStats stats;
    Image image = renderScene(scene, options, &stats);
    if (info) {
      info->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      info->stats = stats;
    }
    return image;
  };
  return r;
}

}  // namespace xval::renderers
