// Whether back faces can be skipped: true only when, for every ray from
// `eye`, the first triangle of `mesh` it hits is a front face (its winding
// normal g = (P1 - P0) x (P2 - P0) points towards the eye). Then a renderer
// looking for first hits may drop the back faces without changing any
// pixel (the fast path's rasteriser does: about half of a closed mesh).
//
// Why it holds: if the mesh bounds a solid whose surface, near every
// point, is the boundary of that solid with g pointing out of it, a ray
// that starts outside the solid can first meet the surface only where it
// enters the solid, i.e. against g. Pieces of the solid may overlap each
// other (a knotted tube that crosses itself): the ray still enters some
// piece first. Three conditions, all checked here:
//   1. the shape is a closed solid: a torus knot tube or a sphere (a plane
//      is open, and its back is visible: never; a model file's mesh:
//      never here, see closedMeshBackFacesNeverFirstHit below);
//   2. every triangle's winding normal agrees with its vertex normals
//      (g . (n0 + n1 + n2) > 0; the tessellators promise outward normals,
//      and this checks the winding against them), and rounding the
//      vertices to float32 has not distorted the mesh: every edge is
//      longer than 1000 x the rounding scale (2^-23 x the largest
//      coordinate). A small object far from the origin fails this: its
//      vertices collapse onto the float grid into zero-area triangles and
//      coincident twins, no longer the surface of a solid (extremes case
//      degenerate_sphere_far);
//   3. the eye is outside the solid, with margin:
//      sphere: |eye - c| > r (1 + 1e-6) + the rounding scale: the mesh's
//        vertices lie on the sphere (up to rounding), so its (convex)
//        faces lie inside it;
//      torus knot: with c_i the centre line at the tessellation's rings
//        and L the longest chord c_i c_{i+1}, every point of the faceted
//        tube between rings i and i+1 lies within rho + L of c_i (each
//        vertex of ring i + 1 is within rho + |c_{i+1} - c_i| of c_i, and
//        the ball is convex), so min_i |eye - c_i| > rho + L + margin puts
//        the eye outside every piece; the margin (1e-6 of the knot's
//        extent plus the rounding scale) covers the float32 rounding of
//        the vertices. And the tube must not fold over
//        itself where the centre line bends: rho < 0.99 x the smallest
//        circumradius of three consecutive c_i (the discrete radius of
//        curvature; adjacent rings then do not cross).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "geometry/mesh.h"
#include "scene/scene.h"

namespace xval {

bool backFacesNeverFirstHit(const Shape& shape, const TriangleMesh& mesh, glm::dvec3 eye);
// For a scene object: the shape's answer when its transform is the
// identity, else false. Condition 3's tests are stated in the shape's own
// coordinates (centre, radii); a transformed object (an ellipsoid, a
// mirrored knot) is not yet given its own test, so its back faces are
// kept: slower, never a different image. A mesh from a model file:
// closedMeshBackFacesNeverFirstHit (below), whatever its transform.
bool objectBackFacesNeverFirstHit(const SceneObject& object, const TriangleMesh& mesh, glm::dvec3 eye);

// The same for any mesh, from its triangles alone (an object's mesh from
// a model file, whatever its transform: the mesh is taken as the renderers
// get it, transformed, mirrored and re-wound, rounded to float32):
//   A. the mesh is the surface of a solid, oriented outwards
//      (geometry/closed_surface.h: no degenerate triangle; every edge,
//      by vertex index, in exactly two triangles running it opposite
//      ways; no two triangles meeting except as their indices say; every
//      component of positive signed volume). Then its winding number w
//      is 0 or 1 per component, so w >= 0 everywhere;
//   B. (no condition on the vertex normals: visibility does not use them);
//   C. the eye is outside the mesh's bounding box (strictly, compared
//      exactly: the vertices are the doubles of the mesh), so w(eye) = 0.
// Why: a ray from the eye meets the surface first at q. Before q it
// crosses nothing, so w = 0 up to q. If q lies inside one triangle and the
// ray crossed it along g (a back face), w would be -1 just past q: not
// possible. A ray that meets a back face first at an edge or a vertex
// meets the triangles sharing it at the same depth, a front one among
// them (the same argument, one ray beside it). So every first hit is on a
// front face, or at a depth a front face shares.
// Open meshes, inconsistent winding, self-intersections (they may leave
// w < 0 somewhere: a figure-eight tube), inside-out components, an eye in
// the box: false, nothing is skipped.
bool closedMeshBackFacesNeverFirstHit(const TriangleMesh& mesh, glm::dvec3 eye);

// In the rasteriser's arithmetic (render/raster.h): culling there drops
// the triangles whose screen-space signed area, computed by the very
// expression the band rasteriser computes, is > 0, so a dropped triangle
// would have been rasterised as a back face, and a kept one is rasterised
// exactly as without culling. Coverage is watertight across an edge shared
// by index (both triangles evaluate the edge function from its lower index,
// bit-identical values of opposite sign, the tie going to one of them), so
// each sample sees the same sequence of crossings as the exact surface,
// up to which of two triangles sharing an edge it falls into. The images
// are then equal bit for bit unless, at some sample, a back face's
// computed 1/z is at least the nearest front face's although the exact
// values are the other way round. That needs the two depths to agree to
// within the rounding of 1/z (a few ulp, relative 1e-15): only at a
// sample within about 1e-15 of a triangle's size from a silhouette edge,
// where the front and the back face sharing the edge both cover it (a
// tie at equal computed 1/z goes to the triangle binned first). There the
// culled image shows the front face, the exact first hit; without culling
// the back face may win by rounding. The tests (front_faces_test) check
// bit identity on whole frames of closed meshes.

// The ray paths' twin of the rasteriser's back-face test: which triangles
// of `mesh` the BVH must hold so that every camera ray from `eye` finds
// the same first hit as with all of them.
//
// Why it holds: a ray eye + t d (t > 0) that meets triangle P0 P1 P2 at q
// has g . (q - P0) = 0 (q is in its plane), so
//   g . d = g . (q - eye) / t = -g . (eye - P0) / t:
// the sign of g . d is the same for every ray from the eye. A triangle
// with g . (eye - P0) < 0 is met by every such ray from behind (g . d > 0),
// a back face, and when backFacesNeverFirstHit holds a back face is never
// a first hit: leaving it out changes no first hit. Three conditions:
//   1. backFacesNeverFirstHit(shape, mesh, eye) holds (the caller checks
//      it: this function does not know the shape);
//   2. every ray starts exactly at `eye` (camera rays do; CameraRays::
//      origin);
//   3. only triangles clearly facing away are dropped: g . e <
//      -1e-9 |g| |e| with e = eye - P0; those within 1e-9 (relative) of
//      edge-on are kept, so the rounding of g . e cannot drop a triangle
//      that faces the eye, and a zero-area triangle (g = 0) is kept.
// Returns the indices of the triangles kept, ascending.
bool facesAwayFromEye(glm::dvec3 p0, glm::dvec3 p1, glm::dvec3 p2, glm::dvec3 eye);
std::vector<uint32_t> trianglesNotFacingAway(const TriangleMesh& mesh, glm::dvec3 eye);

}  // namespace xval
