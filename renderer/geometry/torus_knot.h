// The p-q torus knot's centre line and its smooth, closed tube frame.
//
//   c(t) = ((R + r cos qt) cos pt, (R + r cos qt) sin pt, r sin qt),  t in [0, 2 pi]
//
// The frame (T, N, B) is rotation-minimising (parallel transport, computed
// by the double-reflection method on a fixed fine grid, so it does not
// depend on the mesh's tessellation), with its closing twist spread evenly
// along the curve so that the frame at t = 2 pi equals the frame at t = 0:
// no twist jump at the seam. The tube surface point at angle theta is
//   P = c(t) + rho (cos(theta) N + sin(theta) B)
// and its exact surface normal is cos(theta) N + sin(theta) B (the tube's
// radial direction), orthogonal to T(t) by construction.
#pragma once

#include <glm/glm.hpp>

#include <vector>

#include "scene/scene.h"

namespace xval {

struct CurveFrame {
  glm::dvec3 point, tangent, normal, binormal;
};

class TorusKnotCurve {
 public:
  explicit TorusKnotCurve(const TorusKnot& k, int grid_steps = 1 << 16);

  glm::dvec3 point(double t) const;
  glm::dvec3 derivative(double t) const;  // dc/dt
  // The closed rotation-minimising frame at t in [0, 2 pi].
  CurveFrame frame(double t) const;

 private:
  TorusKnot k_;
  std::vector<glm::dvec3> grid_normals_;  // transported N at grid points
  double step_ = 0.0;
  double twist_ = 0.0;  // radians the transported frame gains over one loop, before the closing correction
};

}  // namespace xval
