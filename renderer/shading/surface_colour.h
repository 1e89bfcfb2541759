// SurfaceColour: the C of the models at a uv: the texture (with the
// material's filter) when there is one, else the base colour; no texture
// fetch without a texture. A trilinear filter looks up the texture's mip
// chain at a level of detail lambda (texture/mip_chain.h); without one
// (lambda 0) that is level 0's bilinear lookup.
#pragma once

#include <glm/glm.hpp>

#include <vector>

#include "geometry/mesh.h"
#include "scene/scene.h"
#include "shading/shader.h"
#include "texture/mip_chain.h"
#include "texture/texel_edge.h"
#include "texture/texture.h"

namespace xval {

template <class T> struct SurfaceColour {
  const Texture* texture = nullptr;
  TextureFilter filter = TextureFilter::Nearest;
  glm::vec<3, T> base{1};
  const MipChain* mips = nullptr;  // the texture's chain, for a trilinear filter

  SurfaceColour(const Material& m, const Texture* tex, const MipChain* chain = nullptr)
      : texture(tex),
        filter(m.texture ? m.texture->filter : TextureFilter::Nearest),
        base(m.base_color),
        mips(chain) {}

  // True when the colour depends on the pixel footprint (lambda).
  bool usesFootprint() const { return texture && filter == TextureFilter::Trilinear && mips; }

  glm::vec<3, T> at(glm::vec<2, T> uv, double lambda = 0.0) const {
    if (!texture) return base;
    if (usesFootprint()) return mips->lookup(uv, lambda);
    return texture->lookup(uv, filter);
  }

  // For a nearest-filtered texture, how near uv is to another texel's pick
  // (texture/texel_edge.h; corners: the triangle's uvs); otherwise
  // kFarFromTexelEdge.
  double texelEdge(glm::vec<2, T> uv, const glm::vec<2, T> corners[3]) const {
    if (!texture || filter != TextureFilter::Nearest) return kFarFromTexelEdge;
    return texelEdgeRoundings(uv, corners, texture->width, texture->height);
  }
};

// Gouraud shading's vertex colours: the model at each vertex (its position
// and normal, the texture at its uv, V towards `eye`), unsaturated. `eye`
// and the mesh are in world coordinates; the vertex is passed to the shader
// relative to shader.origin(), and V is formed in double, both before the
// rounding to T (so a vertex far from the world origin loses nothing).
template <class T>
std::vector<glm::vec<3, T>> gouraudVertexColours(const Shader<T>& shader, const TriangleMesh& m,
                                                 const SurfaceColour<T>& colour, glm::dvec3 eye) {
  using V = glm::vec<3, T>;
  std::vector<V> out(m.positions.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const V p(m.positions[i] - shader.origin());
    const V v(glm::normalize(eye - m.positions[i]));
    out[i] = shader.shade(p, V(m.normals[i]), v, colour.at(glm::vec<2, T>(m.uvs[i])));
  }
  return out;
}

}  // namespace xval
