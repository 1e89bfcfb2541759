// A test camera whose image-plane scale is known in closed form.
#pragma once

#include <cmath>
#include <numbers>

#include "scene/scene.h"

namespace xval::testing {

// At z = 5 looking down -z at the origin, 100 x 100 pixels, 60 degrees:
// k = 100 / (2 tan 30) = 86.60 pixels per unit of the image plane, so a
// world length in the plane z = 0 is k / 5 = headOnPixelsPerUnit() pixels,
// and world x maps to image x = 50 + headOnPixelsPerUnit() x.
inline Camera headOn() {
  Camera c;
  c.position = {0, 0, 5};
  c.target = {0, 0, 0};
  c.up = {0, 1, 0};
  c.fov_y_deg = 60;
  c.width = c.height = 100;
  return c;
}
inline double headOnPixelsPerUnit() { return 100.0 / (2.0 * std::tan(std::numbers::pi / 6)) / 5.0; }

}  // namespace xval::testing
