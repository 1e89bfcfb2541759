// Pinhole camera: the ray through a point of the image plane.
//
// Convention (glTF's, and what every exporter reproduces):
//   forward = normalize(target - position)
//   right   = normalize(cross(forward, up))
//   up'     = cross(right, forward)
// Pixel (i, j), row j = 0 at the top, is sampled at image coordinates
// (x, y) = (i + 0.5, j + 0.5) for one sample per pixel, and the ray is
//   sx = (2 x / W - 1) tan(fov_y / 2) W / H
//   sy = (1 - 2 y / H) tan(fov_y / 2)
//   dir = normalize(forward + sx right + sy up')
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <numbers>

#include "scene/scene.h"

namespace xval {

struct CameraRays {
  glm::dvec3 origin, forward, right, up;
  double tan_half_fov = 0.0, aspect = 1.0;
  int width = 1, height = 1;

  explicit CameraRays(const Camera& c)
      : origin(c.position),
        forward(glm::normalize(c.target - c.position)),
        right(glm::normalize(glm::cross(forward, c.up))),
        up(glm::cross(right, forward)),
        tan_half_fov(std::tan(c.fov_y_deg * std::numbers::pi / 360.0)),
        aspect(double(c.width) / c.height),
        width(c.width),
        height(c.height) {}

  // Unit direction through image coordinates (x, y) in pixels.
  glm::dvec3 direction(double x, double y) const { return directionFromScreen(screenX(x), screenY(y)); }
  // The same in two steps, for callers that reuse sx (a column's) or sy
  // (a row's) across many rays: bit-identical to direction(x, y).
  double screenX(double x) const { return (2.0 * x / width - 1.0) * tan_half_fov * aspect; }
  double screenY(double y) const { return (1.0 - 2.0 * y / height) * tan_half_fov; }
  glm::dvec3 directionFromScreen(double sx, double sy) const {
    return glm::normalize(forward + sx * right + sy * up);
  }
};

}  // namespace xval
