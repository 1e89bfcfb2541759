// Drawing a scene with a user's shader (shader_file/shader_definition.h),
// compiled to GLSL 4.50, on the gl renderer's context (gl/egl_context.h).
//
// The host: the scene's meshes in world space (World is the identity),
// unindexed, one draw per run of meshes of one material (as gl/gl_frame.h),
// each vertex's POSITION, NORMAL and TEXCOORD0 (uv wrapped per triangle, as
// the reference renderer interpolates it) at the locations the compiled
// program gives its inputs. Uniforms are found by introspection (plain or
// in a uniform block, std140, row- or column-major) and set from the scene
// quantity their binding names; every active uniform must have one, and its
// type must be the quantity's. Matrices are supplied as the column-vector
// maths of GLSL (clip = WorldViewProjection * p): the HLSL front end's
// mul(p, M) of a row-vector effect reads them the same way. The camera
// looks down +z of view space; projection maps the near plane (half the
// nearest vertex's depth) to depth 0 and the far one (twice the farthest)
// to 1, GL_ZERO_TO_ONE, as Direct3D. Depth test Less or LessEqual (the
// pass's ZFunc), cleared to 1; the hit mask is where a depth was written
// (depth < 1). No blending, no culling. Each sampler reads the material's
// texture, RGBA32F with its whole mip chain, with its filter (nearest,
// bilinear, trilinear: GL_LINEAR_MIPMAP_LINEAR), repeating.
//
// render.spp = n^2: an n W x n H frame box-filtered as gl's.
#pragma once

#include <memory>
#include <string>

#include "image/image.h"
#include "scene/scene.h"
#include "shader_file/shader_compile.h"
#include "shader_file/shader_definition.h"

namespace xval::gl {

using shaderfile::ShaderProgramText;

// The scene uploaded with the user's program, on a fresh context on this
// thread. Throws GlUnavailable (no context) or std::runtime_error (a
// program that does not compile or link, a uniform or input nothing binds,
// a type mismatch, a GL error), naming what failed.
class ShaderScene {
 public:
  ShaderScene(const Scene& scene, const shaderfile::ShaderDefinition& def, const ShaderProgramText& program);
  ~ShaderScene();
  ShaderScene(const ShaderScene&) = delete;
  ShaderScene& operator=(const ShaderScene&) = delete;

  void draw();  // one frame, waited for (glFinish)
  // draw() and the n W x n H frame: rgba unsaturated as the shader wrote
  // it, alpha the hit mask (1 where a depth was written), row 0 the top.
  Image drawAndRead();
  std::string device() const;
  double setupSeconds() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

// One frame at the camera's resolution, box-filtered; NaN or infinity is
// an ExternalToolError naming the sample.
Image renderWithShader(const Scene& scene, const shaderfile::ShaderDefinition& def,
                       const ShaderProgramText& program);

}  // namespace xval::gl
