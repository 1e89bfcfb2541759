// The triangles of a model file's mesh that the loader drops, the same way
// for every renderer (geometry/model_file.h applies it to each primitive,
// before its normals are computed):
//   1. a triangle that repeats a vertex index ((a, a, b) in any order):
//      two of its corners are one vertex, so it is a segment or a point,
//      of zero area whatever the transforms and the float32 rounding (the
//      corners are the same numbers). No ray hits it: the reference's
//      watertight test (render/ray_triangle.h) computes, for corners
//      A = B, W = bx ay - by ax = 0 and V = -U exactly (the same two
//      products, subtracted the other way), so det = U + V + W = 0 and it
//      returns no hit; a rasteriser gives a zero-area triangle no
//      fragment. Dropping it changes no pixel.
//   2. a triangle whose three indices are those of an earlier triangle of
//      the same mesh, in any order (either winding): the same three
//      vertices, so the same points with the same normals and uvs at each
//      (the flat normal, turned to agree with the vertex normals, is the
//      same too: shading/flat_normals.h). Wherever it is hit its twin is
//      hit at the same point and shades the same; the first one is kept.
// Blender's mesh validation (which its glTF importer runs on every mesh it
// imports) removes exactly these two kinds, keeping the first of twins
// (measured on Blender 3.4.1: "has duplicated vert reference", "Polys i
// and j use same vertices, considering poly j as invalid"); without this
// rule every other renderer would be given triangles Blender is not, and
// its harness refuses a mesh whose corner count differs from the export's
// (exporters/blender/render_gltf.py). Blender keeps triangles of zero area
// whose indices differ (coincident or collinear positions), and so does
// this rule: they stay in every renderer (no ray hits them either).
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace xval {

struct DroppedTriangles {
  std::vector<glm::u32vec3> kept;  // in their order
  size_t repeated_index = 0;       // kind 1
  size_t duplicates = 0;           // kind 2
  size_t dropped() const { return repeated_index + duplicates; }
};

// The rule above on one mesh's triangles.
DroppedTriangles dropDegenerateTriangles(const std::vector<glm::u32vec3>& triangles);

}  // namespace xval
