// POV-Ray's mesh2 and triangles whose three normals are equal.
//
// POV-Ray 3.7's mesh2 parser normalises every `normal_vectors` entry and
// keeps it in single precision; a triangle whose normals n1, n2, n3 (so
// stored) have |n1 - n2|^2 <= 1e-10 and |n1 - n3|^2 <= 1e-10 (its EPSILON)
// is taken as flat, and a flat triangle is shaded with its face normal,
// normalize(cross(P2 - P1, P3 - P1)), not with the normals given. The
// reference renderer shades with the given normals (the model file's, as
// docs/model-files.md says), so the two agree on such a triangle only when
// its normals equal its face normal, up to the direction (POV-Ray turns a
// normal that faces away towards the viewer; the reference's classification
// accounts for that, validate/pixel classes "backfacing normal").
//
// A model file's normals usually are its face normals to float rounding
// (Wuson.ply, Wuson.stl), or differ from them on a few triangles by a
// little (WusonOBJ.obj: 4 triangles of three equal `vn` normals, up to
// 2.9e-5 rad; spider.obj: 10 triangles, up to 1.4e-4 rad;
// these scenes pass against POV-Ray at their declared tolerances), but a
// file may round them coarsely (assimp-testmodels' STL/sphereWithHole.stl
// writes two decimals: all 285 triangles up to 6.8e-3 rad off, 1547/65535
// in the image, 1483 unexplained pixels). The export refuses a mesh with a
// flat triangle whose normals are further from its face normal than
// kPovFlatNormalBoundRad plus what float32 corners can turn a face normal
// by: no normals POV-Ray reads as three equal ones carry a normal other
// than the face's, and three unequal ones would shade the triangle with a
// normal that varies across it.
#pragma once

#include <cstddef>

#include "geometry/mesh.h"

namespace xval {

// The bound on the angle between a flat triangle's normals and its face
// normal (radians, either direction), beyond the rounding of its corners:
// 3e-4 rad, twice the largest measured in the reference scenes' files
// (spider.obj, 1.4e-4) and a twentieth of sphereWithHole.stl's 6.8e-3. A
// normal turned by 3e-4 rad changes N.L by at most 3e-4 (20/65535); such a
// difference is left to the comparison's tolerance, not refused.
inline constexpr double kPovFlatNormalBoundRad = 3e-4;

struct PovFlatTriangles {
  size_t flat = 0;            // triangles POV-Ray's parser takes as flat
  size_t off_face = 0;        // of those, normals further than the bound (and rounding) from the face normal
  double max_angle_rad = 0;   // the largest such angle over the flat triangles
  size_t worst = 0;           // the triangle of that angle
};

// For the mesh as the POV-Ray export writes it (in Phong shading: its
// positions, its normals as normal_vectors, one per vertex).
PovFlatTriangles povFlatTriangles(const TriangleMesh& mesh, double bound_rad = kPovFlatNormalBoundRad);

}  // namespace xval
