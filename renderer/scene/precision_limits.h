// What each precision can compute with: the numbers of a scene the float
// (fast) and double (reference) paths represent and shade without
// overflowing to inf, and so without the NaN of inf x 0 or inf - inf that
// the final saturate would silently turn into black.
//
// A scene is checked for a precision (checkPrecision) when it is loaded
// (for its own render.precision) and again when a renderer is prepared for
// the precision actually used (a --precision option may override it). The
// limits (docs/scene-format.md, "Limits of each precision"):
//
//   coordinate   |x| <= max_coordinate for the camera's position and
//                target and the objects' centres, radii and sizes. The
//                float triangle test (Embree) forms products of three
//                coordinates: (1e12)^3 = 1e36 < 3.4e38 = FLT_MAX; in
//                double (1e100)^3 = 1e300 < 1.8e308.
//   number       |x| <= max_number for every other number (light
//                positions and colours, directions, coefficients, uv
//                repeats, ...): float 1e30, double 1e300.
//   shading      B <= max_shading (float 1e30, double 1e300), where B
//                bounds every value the shader forms (shading/shader.h):
//                  B = 4 C K F max(1, L),
//                  C = max(1, largest surface colour: base_color, or
//                      kMaxTexelValue for an image texture, 1 for brick),
//                  K = max(1, ka + kd + ks) (classic Phong),
//                      max(1, kd + ks + |luma_offset|) (YIQ), 1 otherwise,
//                  F = max(1, largest channel of c0 + c1 + c2) (Forsyth's
//                      family), 1 otherwise,
//                  L = sum over lights of (largest channel of its colour)
//                      x (1 / attenuation.constant when attenuated): each
//                      light's att(d) <= 1 / constant for d >= 0;
//                  4 covers the ambient, diffuse and specular sums.
//                Every intermediate of every model is at most B in
//                magnitude, so none overflows.
#pragma once

#include "scene/scene.h"

namespace xval {

struct PrecisionLimits {
  double max_coordinate;
  double max_number;
  double max_shading;
};

PrecisionLimits precisionLimits(Precision p);

// The bound B above.
double shadingBound(const Scene& scene);

// Throws SceneError naming the scene file, the field, its value, the limit
// and the precision, when `p` cannot compute the scene as described above.
void checkPrecision(const Scene& scene, Precision p);

}  // namespace xval
