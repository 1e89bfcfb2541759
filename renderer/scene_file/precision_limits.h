// What each precision can compute with: the numbers of a scene the float
// (fast) and double (reference) paths represent and shade without
// overflowing to inf, and so without the NaN of inf x 0 or inf - inf that
// the final saturate would silently turn into black.
//
// A scene is checked for a precision (checkPrecision) when it is loaded
// (for its own render.precision) and again when a renderer is prepared for
// the precision actually used (a --precision option may override it). The
// limits (docs/scene-format.md, "Limits of each precision"), float / double:
//
//   coordinate   |x| <= 1e12 / 1e18 for the camera's position and target
//                and the objects' centres, radii and sizes. The float
//                triangle test forms products of three coordinates
//                ((1e12)^3 = 1e36 < FLT_MAX = 3.4e38); Embree carries every
//                ray origin and bounding box in float, in both precisions,
//                and its BVH build multiplies two extents ((1e18)^2).
//   uv repeat    |x| <= 4096 / 1e300: a float uv of magnitude U rounds by
//                U 2^-24, at 4096 an eighth of a texel of a 512-texel
//                texture.
//   number       |x| <= 1e30 / 1e300 for every other number (light
//                positions and colours, directions, coefficients, ...).
//   non-zero     a number that is not 0 is at least 1e-30 / 1e-300 in
//                magnitude (in float 1e-300 rounds to 0: a shininess
//                becomes 0, whose power is 1 everywhere).
//   shading      B <= 1e36 / 1e306, where B bounds every value the shader
//                forms (shading/shader.h):
//                  B = 4 C K F max(1, L) M,
//                  C = max(1, largest surface colour: base_color, or
//                      kMaxTexelValue for an image texture, 1 for brick),
//                  K = max(1, ka + kd + ks) (classic Phong),
//                      max(1, kd + ks + |luma_offset|) (YIQ),
//                      max(1, kd + max(ks, 1) g) (cook_torrance, g its
//                      specularGain(): the bound of its microfacet term
//                      S, ~1 / roughness^3, which is formed before ks
//                      multiplies it), 1 otherwise,
//                  F = max(1, largest channel of c0 + c1 + c2) (Forsyth's
//                      family), 1 otherwise,
//                  L = sum over lights of (largest channel of its colour)
//                      x (1 / attenuation.constant when attenuated): each
//                      light's att(d) <= 1 / constant for d >= 0;
//                  M = 2 (luma_only yiq), 64 (luma_only cie_lstar), 1
//                      otherwise (precision_limits.cpp kLumaOnlyFactor);
//                  4 covers the ambient, diffuse and specular sums.
//                Every intermediate of every model is at most B in
//                magnitude, so none overflows (inf x 0 would be NaN).
//   specular     ks L <= 512 / 2^38: the specular power is taken as 0
//                where it is below 2^-25 / 2^-54 (models::phongSpecular),
//                an error of at most that times ks L: 2^-16, a 16-bit code.
#pragma once

#include "scene/scene.h"

namespace xval {

struct PrecisionLimits {
  double max_coordinate, max_number, min_nonzero, max_uv_repeat, max_shading, max_specular_weight;
};

PrecisionLimits precisionLimits(Precision p);

// The bound B and the specular weight ks L above.
double shadingBound(const Scene& scene);
double specularWeight(const Scene& scene);

// Throws SceneError naming the scene file, the field, its value, the limit
// and the precision, when `p` cannot compute the scene as described above.
void checkPrecision(const Scene& scene, Precision p);

}  // namespace xval
