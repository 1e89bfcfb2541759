// Affine transforms of a triangle mesh: the object "transform" of a scene
// (scale, then rotate, then translate) and a model file's node matrices.
//
// An Affine maps a point p to  A p + o  (A a 3x3 matrix, o a vector).
//   Composition: (F after G) p = F.A (G.A p + G.o) + F.o, i.e.
//     A = F.A G.A,  o = F.A G.o + F.o                      (then(G, F))
//   Normals: a tangent t of the surface maps to A t; a normal n must stay
//     orthogonal to every mapped tangent: n' . (A t) = 0 for all t with
//     n . t = 0, so n' is parallel to A^-T n (the inverse transpose):
//       n' = normalize(A^-T n).
//     A^-T = cof(A) / det(A), cof the cofactor matrix; dividing by det keeps
//     the sign, so n' points to the same side of the surface as n did.
//   Winding: the winding normal g = (P1 - P0) x (P2 - P0) maps to
//     (A e1) x (A e2) = cof(A) g = det(A) A^-T g. When det(A) < 0 (a
//     mirroring transform) g then points against n', so the triangles are
//     re-wound (vertices 1 and 2 swapped) to keep the mesh's rule: counter-
//     clockwise seen from the side the vertex normals point to.
//   A singular A (det = 0) has no normal map: refused.
//
// ObjectTransform, the scene's "transform" object:
//   "scale":     s, a number (s, s, s) or [sx, sy, sz]; default 1
//   "rotate":    {"axis": [x, y, z], "angle_deg": a}: a right-handed turn by
//                a degrees about the unit axis u = axis / |axis| (Rodrigues:
//                R = cos a I + sin a [u]x + (1 - cos a) u u^T); default none
//   "translate": t = [x, y, z]; default 0
//   applied in that order:  p' = R (S p) + t,  S = diag(sx, sy, sz).
//   Then A = R S and A^-T = R S^-1 (R is orthonormal): a normal is scaled by
//   1 / s per axis, turned, and renormalised. det A = sx sy sz.
#pragma once

#include <glm/glm.hpp>

#include <stdexcept>
#include <string>

#include "geometry/mesh.h"

namespace xval {

struct Affine {
  glm::dmat3 linear{1.0};  // A (glm is column-major: linear[c][r])
  glm::dvec3 offset{0.0};  // o

  glm::dvec3 point(glm::dvec3 p) const { return linear * p + offset; }
  double determinant() const { return glm::determinant(linear); }
  bool mirrors() const { return determinant() < 0.0; }
};

// first, then second: p -> second(first(p)).
inline Affine then(const Affine& first, const Affine& second) {
  return {second.linear * first.linear, second.linear * first.offset + second.offset};
}

// Rotation and ObjectTransform, the values, are defined in scene/scene.h.

class TransformError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// R of the rotation. Throws TransformError for a zero or non-finite axis or
// a non-finite angle (the message names the field: "rotate.axis").
glm::dmat3 rotationMatrix(const Rotation& r);

// T R S as an Affine. Throws TransformError when a scale component is 0 or
// not finite ("scale[1]"), for a bad rotation, or a non-finite translation.
Affine toAffine(const ObjectTransform& t);

// The mesh mapped by `f`: positions f(p), normals normalize(A^-T n),
// triangles re-wound when f mirrors. uvs are unchanged. Throws
// TransformError when A is singular or not finite.
TriangleMesh transformed(const TriangleMesh& mesh, const Affine& f);

}  // namespace xval
