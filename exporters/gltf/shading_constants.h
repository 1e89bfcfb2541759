// Every constant the Blender harness's shader nodes need, prepared once
// here from the reference renderer's own code (Shader<double>,
// prepareLights, models.h), so that exporters/blender/render_gltf.py
// computes none of its own and only wires these values into nodes.
//
// Written as JSON into the glTF scene's extras (`xval_shading`), in the
// scene's world frame (+y up). The harness converts Blender's position
// P_b into that frame with `blender_to_world` (the glTF importer maps
// (x, y, z) to (x, -z, y); its inverse is a permutation with one sign, so
// the three dot products are exact).
//
//   shading         "phong" | "flat" | "gouraud"
//   normalize_normal phong: N = normalize(interpolated normal), or (false,
//                   the paper's listing) the interpolated normal as it is
//   eye             the camera position: V = normalize(eye - P)
//   base_colour     C when there is no texture; texture_filter otherwise
//                   ("nearest" | "bilinear" | "trilinear")
//   model           the model's name; its constants (by model):
//     classic_phong  ka, kd, ks, shininess, course, specular (ks != 0),
//                    ka_ambient = ka A
//     yiq_luma       kd, ks, shininess, luma_offset, specular,
//                    ambient_luma = Y(A), luma_row (Y of the listing)
//     forsyth family ambient = A, c0, c1, c2, c0_minus_c2 (hemispherical),
//                    factor and wrap_divisor = 1 + factor (wrap_around)
//     minnaert       ambient = A, kd, k
//     blinn_phong    ka, kd, ks, shininess, specular (ks != 0), ka_ambient = ka A
//     oren_nayar     ambient = A, kd, sigma, cycles (variant cycles), a and b
//                    (models::orenNayarQualitativeAB / orenNayarCyclesAB)
//     cook_torrance  ambient = A, kd, ks, specular (ks != 0), distribution
//                    ("ggx" | "beckmann"), geometry ("smith" |
//                    "cook_torrance"), fresnel ("none" | "schlick"), f0,
//                    roughness (alpha), vgroove_min_vh (models.h)
//   lights          the non-ambient lights, in scene order:
//     kind          "point" | "spot" | "directional"
//     colour, luma  Lc and Y(Lc) (normalised luma, models::lightLuma)
//     position      point and spot
//     to_light      directional: L = -normalize(direction)
//     minus_axis, cos_cutoff   spot: lit iff dot(L, minus_axis) >= cos_cutoff
//                   (= dot(-L, axis) exactly: negation is exact)
//     attenuated    false when (c, l, q) = (1, 0, 0): att = 1, no node
//     attenuation   [c, l, q]: att = 1 / (c + l d + q d^2)
#pragma once

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace xval {

nlohmann::ordered_json shadingConstants(const Scene& scene);
// The constants of an object of `material` in `scene` (its own material,
// scene.h materialOf): written into that glTF material's extras.
nlohmann::ordered_json shadingConstants(const Scene& scene, const Material& material);

}  // namespace xval
