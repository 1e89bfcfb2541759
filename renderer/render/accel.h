// Accel: closest-hit ray queries over the scene's triangle meshes, with
// Embree's BVH.
//
// Float path: Embree's own triangles and single-precision intersection,
// traced in 16-ray packets by the renderer.
// Double path (the reference): Embree user geometry; Embree traverses its
// BVH over boxes padded outward (so float rounding of the ray cannot make
// it skip a box the exact ray enters), and every candidate triangle is
// tested by the double-precision watertight test (render/ray_triangle.h)
// against the double ray. The closest double hit wins; the float ray's
// t_far is only ever shrunk to a value rounded up, so no closer candidate
// is culled.
#pragma once

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "scene/scene.h"

namespace xval {

struct Hit {
  bool hit = false;
  uint32_t mesh = 0, triangle = 0;
  double t = 0.0, b1 = 0.0, b2 = 0.0;  // barycentrics of vertices 1 and 2
};

class Accel {
 public:
  // only: per mesh, the triangles to put in the BVH (nullopt: all of them;
  // the renderer leaves out back faces that cannot be a camera ray's first
  // hit, geometry/front_faces.h trianglesNotFacingAway). Hits name triangles by their mesh index.
  Accel(const std::vector<TriangleMesh>& meshes, Precision precision,
        const std::vector<std::optional<std::vector<uint32_t>>>& only = {});
  ~Accel();
  Accel(const Accel&) = delete;
  Accel& operator=(const Accel&) = delete;

  Hit intersect(glm::dvec3 origin, glm::dvec3 dir) const;

  // A packet of kPacketSide^2 rays from one origin (a kPacketSide square of
  // pixels): the float path traces them together as one Embree 16-ray
  // packet with the coherent-rays hint; the double path one at a time.
  // valid[r] false: dirs[r] is ignored and out[r] is set to no hit.
  static constexpr int kPacketSide = 4;
  void intersectPacket(glm::dvec3 origin, const glm::dvec3* dirs, const bool* valid, Hit* out) const;

  struct DoubleGeometry;  // per-mesh data for the user-geometry callbacks

 private:
  Hit intersectFloat(glm::dvec3 origin, glm::dvec3 dir) const;
  Hit intersectDouble(glm::dvec3 origin, glm::dvec3 dir) const;

  // The mesh triangle of an Embree primitive.
  uint32_t triangleOf(uint32_t mesh, uint32_t prim) const {
    return mesh < only_.size() && only_[mesh] ? (*only_[mesh])[prim] : prim;
  }

  Precision precision_;
  std::vector<std::optional<std::vector<uint32_t>>> only_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<std::unique_ptr<DoubleGeometry>> double_geoms_;
  std::string error_;
};

}  // namespace xval
