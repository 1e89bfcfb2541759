// Whether a triangle mesh is the surface of a solid, oriented outwards:
// the fact geometry/front_faces.h needs to skip the back faces of a mesh
// read from a model file (where nothing promises a closed surface).
//
// The quantity behind it: the winding number w(x) of the mesh around a
// point x off the surface (the sum of the triangles' signed solid angles
// over 4 pi). For a closed, consistently oriented mesh (below) w is an
// integer, constant off the surface, 0 far away, and it changes by exactly
// one where a path crosses the surface through the inside of one
// triangle: +1 when the path crosses against the winding normal g =
// (P1 - P0) x (P2 - P0), -1 when it crosses along g.
//
// The conditions, checked on the mesh exactly as the renderers get it
// (float32 coordinates held in doubles, and the vertex indices):
//   1. no degenerate triangle: three distinct indices and
//      |g| > 1e-10 x (longest edge)^2;
//   2. closed and consistently oriented: every edge {a, b} (vertex indices)
//      belongs to exactly two triangles, one running it a -> b and the
//      other b -> a (then the triangles form a 2-cycle, and w is as
//      stated);
//   3. embedded: two triangles meet only where their indices say: not at
//      all when they share no vertex index, only along the shared edge or
//      at the shared vertex otherwise (tests below, each conservative:
//      "disjoint" only with a margin above the double rounding). Then
//      each edge-connected component is a closed surface without
//      self-intersections and bounds one solid (Jordan-Brouwer): its own
//      w_c is 1 inside it and 0 outside, or -1 inside and 0 outside;
//   4. outward: each component's signed volume sum det(P0, P1, P2) / 6
//      (about the component's first vertex) is positive by more than
//      its rounding, 1e-9 of the sum of the terms' magnitudes (so w_c =
//      +1 inside; a component turned inside out, such as the inner wall of
//      a hollow ball modelled as two surfaces, fails and nothing is
//      skipped).
// Together: w = sum_c w_c >= 0 everywhere, and every component's w_c >= 0.
//
// The embedding tests for two triangles T1, T2 (unit normals n1, n2):
//   no shared index: separated along one of the axes n1, n2, ei x fj,
//     n1 x ei, n2 x fj (the separating-axis theorem for two triangles:
//     the face normals, the edge pairs, and for coplanar ones the edges'
//     in-plane normals), with a gap over 1e-10 of the mesh's extent;
//   a shared edge: the triangles' planes meet only in the edge's line
//     unless they coincide, so they meet only in the edge unless they are
//     folded onto each other (coplanar, n1 . n2 < 0); refused when
//     n1 . n2 < 0 and |n1 x n2| < 1e-6;
//   a shared vertex v: T1 and T2 are convex and contain v, so they meet
//     elsewhere exactly when they have a common direction from v. Either
//     the planes cross in the line v + t u, u = n1 x n2, and the common
//     direction would be +u or -u: disjoint when no sign of u lies in
//     both corners (u = alpha p + beta q with alpha, beta >= 0 for
//     T1's edge vectors p, q from v; 1e-9 of slack); or T2 projected
//     onto T1's plane (or T1 onto T2's) meets T1 only at v: two convex
//     corners at v overlap exactly when one holds an edge direction of
//     the other. Either suffices.
// Candidate pairs: the triangles whose bounding boxes (grown by the gap)
// overlap, found through a uniform grid; the others are disjoint. The work
// is bounded (at most 256 n + 2^24 pairs of triangles in common cells, 64
// n + 2^20 cell entries, n < 2^24): a mesh beyond that is "not checked",
// i.e. not claimed.
#pragma once

#include <string>

#include "geometry/mesh.h"

namespace xval {

// Empty when conditions 1 to 4 hold; else which one fails, for the first
// triangle (or pair) found failing it.
std::string whyNotAnOutwardSolid(const TriangleMesh& mesh);

}  // namespace xval
