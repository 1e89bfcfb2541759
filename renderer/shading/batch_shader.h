// BatchShader: the fast path's shading of many hits at once, SIMD across
// hits (Google Highway, its widest target on the running CPU: SSE4, AVX2
// or AVX-512).
//
// The same formulas, in the same order of float operations, as the scalar
// path (renderer.cpp's per-hit shading: Phong-mode interpolation,
// Shader<float>::shade, SurfaceColour, models::saturate), so its results
// are bit-identical to it; the unit test BatchShader.* checks that on every
// pixel of several scenes. Where the scalar path branches on a rare case,
// the kernel finishes those lanes with the very same scalar code:
//   - the specular power exp(n log1p(-h)), needed only inside a highlight
//     (models::phongSpecular; elsewhere it is 0 or 1 without a call);
//   - the light vector when |D|^2 leaves float's normal range
//     (towardsLight's rescaling).
//
// Covers: shading mode phong; models yiq_luma and classic_phong (variant
// paper); point, directional and spot lights with or without attenuation;
// texture (nearest or bilinear; not trilinear, whose level needs each hit's
// footprint) or base colour; the normal re-normalised (not the scene
// option normalize_normal false, with its normalize(R)); not the material's
// luma_only mode. Anything else (flat, gouraud, course variant, Forsyth's
// family, minnaert, blinn_phong, oren_nayar, cook_torrance) is not built: batchShading()
// returns nothing and the renderer shades one hit at a time.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "scene/scene.h"
#include "shading/lights.h"
#include "texture/texture.h"

namespace xval {

struct BatchShading {
  enum class Model { YiqLuma, ClassicPhong };
  Model model = Model::YiqLuma;
  float ka = 1, kd = 1, ks = 1, shininess = 55, luma_offset = 0.1f;
  bool specular = false;
  glm::vec3 ambient{0};  // summed ambient light colour
  float ambient_luma = 0;
  std::vector<PreparedLight<float>> lights;  // positions relative to the eye
  const Texture* texture = nullptr;          // packed (Texture::pack) or not
  TextureFilter filter = TextureFilter::Nearest;
  glm::vec3 base{1};
};

// The scene's shading for the kernel (light positions relative to `eye`,
// as the renderer's shading coordinates), or nothing when the kernel does
// not cover the scene (see above).
std::optional<BatchShading> batchShading(const Scene& scene, const Texture* texture, glm::dvec3 eye);

// One mesh in shading coordinates (positions relative to the eye), float,
// each vertex's attributes side by side so one cache line serves a vertex:
// vertices[8 i ..] = p.x p.y p.z n.x n.y n.z u v.
struct BatchMesh {
  std::vector<float> vertices;
  const glm::u32vec3* triangles = nullptr;
};
inline constexpr int kBatchVertexFloats = 8;
BatchMesh batchMesh(const std::vector<glm::vec3>& p, const std::vector<glm::vec3>& n,
                    const std::vector<glm::vec2>& uv, const std::vector<glm::u32vec3>& triangles);

// Pad the hit arrays to a multiple of this; padding entries must name a
// valid triangle (they are shaded and their results ignored).
inline constexpr size_t kBatchPad = 16;

// Shades hits k in [0, count): triangle tri[k], barycentrics b1[k], b2[k]
// (b0 = 1 - b1 - b2), eye at the origin. Writes the saturated colour to
// r[k], g[k], b[k]. All arrays hold count rounded up to kBatchPad.
void shadeBatch(const BatchShading& s, const BatchMesh& m, size_t count, const std::uint32_t* tri,
                const float* b1, const float* b2, float* r, float* g, float* b);

// The instruction set shadeBatch runs with on this CPU (e.g. "AVX2").
const char* batchShaderTarget();

}  // namespace xval
