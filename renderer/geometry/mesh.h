// TriangleMesh: the one geometry representation every renderer consumes.
//
// Every shape is tessellated to this; the reference renderer, the POV-Ray
// mesh2 and the glTF buffers hold exactly these positions, normals, uvs and
// triangles. Triangles wind counter-clockwise seen from the side their
// vertex normals point to. uv follows glTF: (0,0) is the image's top-left
// texel corner, v runs down the image.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace xval {

struct TriangleMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // unit length
  std::vector<glm::dvec2> uvs;
  std::vector<glm::u32vec3> triangles;

  size_t vertexCount() const { return positions.size(); }
  size_t triangleCount() const { return triangles.size(); }
};

TriangleMesh tessellateTorusKnot(const TorusKnot& k);
TriangleMesh tessellateSphere(const UvSphere& s);
TriangleMesh tessellatePlane(const Plane& p);
// The shape's mesh with every attribute rounded to float32 (the precision of
// glTF buffers and POV-Ray's mesh2), so that all renderers trace the very
// same triangles. Normals stay unit length to float32 precision.
// A model file's shape has one mesh per primitive: geometry/scene_meshes.h
// (tessellate refuses it, std::invalid_argument).
TriangleMesh tessellate(const Shape& shape);
// The same, not rounded (for a transform to map first).
TriangleMesh tessellateExact(const Shape& shape);
// Every attribute of `m` rounded to the nearest float32, in place (the last
// step before any renderer sees a mesh: after a model file's node and
// object transforms too).
void roundToFloat(TriangleMesh& m);

}  // namespace xval
