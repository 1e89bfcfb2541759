// What the gl renderer (gl/gl_frame.h) and the shader renderer
// (shader_file/shader_frame.h) both do on an OpenGL 4.5 context: compile a stage,
// upload a texture as RGBA32F, make the RGBA32F + DEPTH32F targets, read
// the frame back top row first, and finish a supersampled frame.
// All calls on the thread whose context is current; errors throw
// std::runtime_error naming what failed.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "camera/camera.h"
#include "common/export_common.h"
#include "geometry/scene_meshes.h"
#include "image/image.h"
#include "scene/scene.h"

namespace xval::gl {

using GlName = unsigned int;  // GLuint, without the GL headers

// The scene's triangles as both renderers draw them: unindexed, the meshes
// in scene order, one run per run of meshes of one material slot. `corner`
// is called for each triangle's three corners in order with the mesh's
// index, the triangle's, the corner's vertex and its uv wrapped per
// triangle (frac(uv0) + (uv_k - uv0), the reference's interpolateUv).
struct DrawRun {
  size_t slot = 0;  // MaterialSlots index
  int first = 0, count = 0;  // corners
};
struct SceneDraws {
  std::vector<DrawRun> runs;
  // The fitted near plane: half the smallest view depth of any corner, or
  // 1e-6 of the largest when a corner lies at or behind the eye.
  double near = 0.0;
  double max_depth = 0.0;  // the largest view depth (0 with none ahead)
};
SceneDraws walkSceneTriangles(const SceneMeshes& meshes, const MaterialSlots& slots, const CameraRays& camera,
                              const std::function<void(size_t mesh, size_t triangle, uint32_t vertex,
                                                       glm::dvec2 uv)>& corner);

// Throws the GL error, if any, naming `what`.
void checkGl(const char* what);

// A compiled stage (`stage`: GL_VERTEX_SHADER, GL_FRAGMENT_SHADER); on
// failure the message is "OpenGL: the <name> does not compile: <log>".
GlName compileStage(unsigned int stage, const char* source, const std::string& name);
// The linked program of a vertex and a fragment stage's source, each
// compiled with compileStage (named `vertex_name`, `fragment_name`); on
// failure "OpenGL: the shader program does not link: <log>". The stages
// are deleted either way.
GlName buildProgram(const char* vertex, const std::string& vertex_name, const char* fragment,
                    const std::string& fragment_name);

// Throws when a width x height texture exceeds GL_MAX_TEXTURE_SIZE.
void checkTextureSize(int width, int height);

// `spec`'s texture as RGBA32F (alpha 1), `levels` mip levels (1: the image
// only; more: filled by glGenerateTextureMipmap). Throws when it exceeds
// GL_MAX_TEXTURE_SIZE.
GlName uploadTextureRgba32f(const TextureSpec& spec, bool mip_chain);

// An RGBA32F colour and DEPTH32F depth framebuffer of w x h.
struct FrameTargets {
  GlName fbo = 0, colour = 0, depth = 0;
};
FrameTargets makeFrameTargets(int width, int height);
void deleteFrameTargets(FrameTargets& t);

// The fixed state both renderers draw with: clip depth 0..1
// (GL_ZERO_TO_ONE), the depth test with `depth_func` (GL_GREATER, GL_LESS,
// GL_LEQUAL) and depth writes, no culling, blending, multisampling or
// dithering, the whole w x h frame of `t`, the vertex array `vao` bound.
void setDrawState(unsigned int depth_func, const FrameTargets& t, int width, int height, GlName vao);

// The colour attachment, row 0 the top: rgba as drawn (alpha as drawn).
Image readColourTopDown(const FrameTargets& t, int width, int height);
// The depth attachment, row 0 the top.
std::vector<float> readDepthTopDown(const FrameTargets& t, int width, int height);

// The n W x n H frame `fine` (rgba, alpha the hit mask) finished as the
// renderers' images are: NaN or infinity an ExternalToolError naming
// `renderer` and the sample, raw = the unsaturated colour, box-filtered
// (common/supersample.h).
Image finishFrame(Image fine, int n, const std::string& renderer);

}  // namespace xval::gl
