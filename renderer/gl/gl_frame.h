// Rendering a scene through OpenGL 4.5 core (gl/egl_context.h, the GLSL
// port gl/glsl_models.h): the gl renderer's work.
//
// The scene is tessellated as for every renderer (geometry/mesh.h) and
// drawn as unindexed triangles, each vertex carrying its position minus the
// eye (subtracted in double, then rounded to float: camera-relative, as the
// reference renderer shades), its normal, its uv wrapped per triangle
// (frac(uv0) + (uv_k - uv0), the reference's interpolateUv) and, for flat
// shading, its triangle's normal (shading/flat_normals.h). Targets: an
// RGBA32F colour renderbuffer (unsaturated model colour, alpha 1 on a hit,
// cleared to 0) and a 32-bit float depth renderbuffer with reversed Z
// (depth = near / z, cleared to 0, test GREATER, infinite far plane), the
// near plane fitted to the scene: half the smallest view depth of any
// vertex, or 1e-6 of the largest when a vertex lies at or behind the eye.
// Each material's texture is uploaded as RGBA32F without mip-maps and read
// only by texelFetch; with filter trilinear it has the full mip chain
// (glGenerateTextureMipmap) and is read by texture() through the sampler,
// LINEAR_MIPMAP_LINEAR, REPEAT, no anisotropy. The meshes are drawn in
// scene order, one draw per run of meshes of one material, with that
// material's uniforms and texture, and a program specialised to its
// switches (glsl_models.h ShaderVariant: model, variant, texture filter,
// shading, luma-only mode, the lights' kinds), one per distinct variant.
// Back faces culled (GL_BACK, counter-clockwise front) in the draws whose
// meshes pass objectBackFacesNeverFirstHit (geometry/front_faces.h: a
// closed, untransformed knot or sphere, or a closed model mesh, seen from
// outside: a back face is never the first hit, so culling changes a pixel
// only where a back face won a silhouette tie by rounding), not elsewhere.
// No blending, no multisampling.
//
// render.spp = n^2: the frame is n W x n H, one fragment on each pixel
// centre (common/supersample.h), box-filtered as the external renderers'
// images are: each sample saturated, then averaged; raw keeps the
// unsaturated mean.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"

namespace xval::gl {

// A scene uploaded to a fresh context on this thread; all its calls must be
// made on the thread that made it. Throws GlUnavailable (no context) or
// std::runtime_error (a shader that does not compile, a framebuffer that
// is incomplete, a GL error), naming what failed.
class GlScene {
 public:
  explicit GlScene(const Scene& scene);
  ~GlScene();
  GlScene(const GlScene&) = delete;
  GlScene& operator=(const GlScene&) = delete;

  // Draws one frame and waits for it (glFinish); nothing is read back.
  void draw();
  // draw() and the n W x n H frame read back: rgba unsaturated, alpha the
  // hit mask, row 0 at the top.
  Image drawAndRead();
  // GL_RENDERER and GL_VERSION of the context.
  std::string device() const;
  // Seconds the constructor took (context, shaders, uploads).
  double setupSeconds() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

// One frame of the scene at its camera's resolution: GlScene, drawAndRead,
// the box filter. Throws as GlScene; a NaN or infinite sample is an
// ExternalToolError naming the first one (common/export_common.h
// requireFinite). The render.spp grid is checked first (subpixelGrid).
// `renderer`: the id of the registry entry rendering it (renderers/gl.cpp),
// which labels the errors.
Image renderWithGl(const std::string& renderer, const Scene& scene, std::string* device = nullptr);

}  // namespace xval::gl
