// The GLSL (4.50 core) port of the lighting models, lights, texture lookups
// and shading modes: the vertex and fragment shader of the gl renderer
// (gl/gl_frame.h). The formulas are those of shading/models.h,
// shading/lights.h, shading/shader.h and texture/texture.h (docs/models.md);
// where the paper's HLSL listing (docs/gl-renderer.md quotes the lines)
// defines a step, the port writes it as the listing does:
//   R  = normalize(2 N (N.L) - L)
//   S  = pow(saturate(R.V), n)          (the reference: from |R - V|)
//   YIQ: RGB -> YIQ, Y' = Y Dl + S - off, YIQ -> RGB with the listing's two
//        matrices (the reference: the one-dot-product reduction)
// and otherwise as the reference renderer does: the interpolated normal
// re-normalised (zero stays zero), uv wrapped per triangle, n = 0 gives
// S = 1, clamps map NaN to 0, towardsLight's rescaling of far and near
// lights, and the texture read texel by texel (texelFetch) with the
// reference's nearest and bilinear rules, never by the sampler. Two of the
// listing's own choices are the scene's to make: the normal not
// re-normalised (normalize_normal false), and filter trilinear, which is
// the hardware's own sampler (LINEAR_MIPMAP_LINEAR, glGenerateMipmap's
// chain, its level of detail), the one lookup not written out here.
#pragma once

#include <string>
#include <vector>

#include "shading/model/registry.h"

namespace xval::gl {

// The shaders' inputs, fixed here once (gl_frame.cpp binds them).
inline constexpr int kAttribPosition = 0;    // vec3: vertex - eye (camera-relative, from double)
inline constexpr int kAttribNormal = 1;      // vec3: the vertex normal
inline constexpr int kAttribUv = 2;          // vec2: frac(uv0) + (uv_k - uv0) of its triangle
inline constexpr int kAttribFaceNormal = 3;  // vec3: flat shading's normal (shading/flat_normals.h)
inline constexpr int kLightsBinding = 0;     // the lights' uniform block
inline constexpr int kTextureUnit = 0;       // the RGBA32F texture
inline constexpr int kCodesUnit = 2;         // the RGBA8UI texture of 8-bit codes (ShaderVariant::texture_codes)

// The GLSL name of a model's id constant ("MODEL_LAMBERT"): both shaders
// declare one per model of the registry (shading/model/registry.h), equal
// to its ModelId, and the shaders' code tests k_model against those names.
std::string glslModelConstant(ModelId id);

// What a program is specialised on: every switch that selects a code path,
// compiled in as a constant (k_<name> in the GLSL) rather than read from a
// uniform. llvmpipe runs a fragment shader on a vector of fragments with
// an execution mask and does not skip a branch that no lane takes, so a
// branch on a uniform costs its whole body; with the switches constant the
// compiler drops every path the draw does not take, and the paths it takes
// compute what they computed before. The numbers (ka, kd, n, the colours,
// the lights' positions and colours) stay uniforms. One program per
// distinct variant of a scene's draws (gl_frame.cpp).
struct ShaderVariant {
  int shading = 2;  // 0 flat, 1 gouraud, 2 phong
  ModelId model{};
  bool course = false;            // classic_phong's course variant
  bool specular = false;          // ks != 0
  bool on_cycles = false;         // oren_nayar's variant cycles
  int ct_distribution = 0, ct_geometry = 0, ct_fresnel = 0;  // models::Microfacet* enums' values
  int texture = 0;                // 0 none (u_base), 1 nearest, 2 bilinear, 3 trilinear
  // Nearest, bilinear: the texture read as its 8-bit codes c (RGBA8UI), each
  // value c / 255 in float, where every texel's value is that (Texture::
  // codes_are_c_over_255) and this driver's GLSL division gives it exactly
  // (gl_frame.cpp): the same texels in a quarter of the memory; llvmpipe's
  // bilinear lookup waits on memory (docs/gl-renderer.md).
  bool texture_codes = false;
  bool normalize_normal = true;   // phong: re-normalise the interpolated normal
  int luma_only = 0;              // the luma-only mode: 0 off, 1 yiq, 2 cie_lstar (LumaSpace + 1)
  std::vector<int> light_kinds;   // per light of the draw's set: 0 point, 1 directional, 2 spot
  std::vector<bool> light_attenuated;  // per light: 1 / (c + l d + q d^2) applies
  // Per light: towardsLight's rescaling can be reached from the draw's
  // triangles (shading/lights.h towardsLightMayRescale); where it cannot,
  // the test for it is left out (llvmpipe would run the rescaling for
  // every fragment: its divisions and square root), the result the same.
  std::vector<bool> light_may_rescale;
  bool operator==(const ShaderVariant&) const = default;
};

// A compute shader (256 invocations) writing codeValue(c) for c = 0..255,
// the shaders' decoding of an 8-bit code, to float v[c] of the storage
// buffer at binding 0: gl_frame.cpp checks it against c / 255.
std::string codeValueCheckSource();

std::string vertexShaderSource(const ShaderVariant& variant);
std::string fragmentShaderSource(const ShaderVariant& variant);

}  // namespace xval::gl
