// gl: the models as GLSL through OpenGL 4.5 core, in this process
// (gl/gl_frame.h), on a context from EGL's surfaceless platform
// (gl/egl_context.h): Mesa's llvmpipe on a machine without a GPU, the
// vendor's driver where there is one.
//
// A rasteriser running the paper's shader as a real-time renderer would:
// the GLSL port (gl/glsl_models.h) follows the paper's HLSL listing where
// the listing defines a step and the reference renderer otherwise
// (docs/gl-renderer.md). RGBA32F colour, 32-bit float reversed-Z depth
// with a fitted near plane, the texture as RGBA32F read texel by texel.
//
// Parameters (RenderRequest): none are used (no outside tool, no work
// folder, no time-out; a frame takes milliseconds). Version: xval's (the
// device, GL_RENDERER and GL_VERSION, is printed by `xval bench`).
// prepare_frames: the scene uploaded once (GlScene); a frame is clear,
// draw, glFinish at n W x n H (render.spp = n^2), nothing read back.
// Unavailable, with EGL's reason, when no OpenGL 4.5 core context can be
// made (no EGL vendor library, no surfaceless platform, no 4.5 core
// driver): then every gl render fails with that reason, never a pass.
#include <cmath>
#include <chrono>
#include <memory>

#include "gl/egl_context.h"
#include "gl/gl_frame.h"
#include "common/export_common.h"
#include "common/supersample.h"
#include "renderers/renderer.h"

namespace xval::renderers {

Renderer glRenderer() {
  Renderer r;
  r.id = "gl";
  r.job_cost = {0.2, 1.0, 2.0};  // validate/validation/job_cost.h
  r.display_name = "OpenGL";
  r.subject = "the OpenGL renderer";
  r.summary = "the models as GLSL through OpenGL 4.5 core on EGL (surfaceless; Mesa llvmpipe without a GPU)";
  r.missing = [] { return gl::glUnavailableReason(); };
  // docs/precision-models.md, gl.
  r.precision = {1.0, 1.0, std::ldexp(1.0, -10), 1e-5, 0.0,
                 "Mesa llvmpipe: float32 varyings and normals, exp2/log2 pow, GPU level of detail; RGBA32F"};
  // A supersampled frame within the image limits (common/supersample.h).
  r.cannot_express = [](const Scene& scene) -> std::string {
    try {
      subpixelGrid(scene);  // the n W x n H frame must be an image xval reads back
    } catch (const ExportError& e) {
      return e.what();
    }
    return "";
  };
  r.render = [id = r.id](const Scene& scene, const RenderRequest&, RenderInfo* info) {
    const auto t0 = std::chrono::steady_clock::now();
    Image image;
    try {
      image = gl::renderWithGl(id, scene);
    } catch (const gl::GlUnavailable& e) {
      throw ExternalToolError(id + ": unavailable: " + e.what());
    }
    if (info) info->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return image;
  };
  r.prepare_frames = [id = r.id](const Scene& scene) {
    std::shared_ptr<gl::GlScene> prepared;
    try {
      prepared = std::make_shared<gl::GlScene>(scene);
    } catch (const gl::GlUnavailable& e) {
      throw ExternalToolError(id + ": unavailable: " + e.what());
    }
    return FrameLoop{[prepared] { prepared->draw(); }, prepared->device(), prepared->setupSeconds()};
  };
  return r;
}

}  // namespace xval::renderers
