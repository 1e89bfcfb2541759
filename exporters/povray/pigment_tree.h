// PigmentTree: a colour that POV-Ray computes exactly, built from blend maps.
//
// Every node is linear in its leaves, so constant factors and sums can be
// pushed down to the leaves:
//   Leaf:  out = M C + b   (C = the texture colour at the hit's uv, M 3x3)
//   Map:   a pattern value v in [0,1] and entries (v_i, node_i); POV-Ray
//          interpolates linearly between adjacent entries (pigment_map)
//   Sum:   sum of children (POV-Ray's `average` pigment_map, each child
//          scaled by the number of children)
// A Map over a Grey pattern (pigment_pattern) has a tree of its own inside
// the pattern: it is not a leaf of the map, and mapLeaves / scaled leave it
// as it is (the pattern value must not change when the map is scaled).
// toSdl() writes the tree as one POV-Ray pigment. The texture colour C is
// read through `XvalTexture(x, y, z)` (a function of an image_map) inside a
// uv_mapping pigment at the leaves only, so position patterns above them
// see world coordinates.
#pragma once

#include <glm/glm.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace xval::pov {

// The patterns the maps blend over, as values (patternSdl writes them):
//   Slope        (1 + N.L) / 2: `slope { point_at P }` (L = normalize(P - x))
//                or `slope { D }` (L = D), each with `sine_wave frequency
//                -0.5 phase 0.75` (docs/povray-export.md)
//   Attenuation  function c / (c + l d + q d^2), d = |x - P|, in (0, 1]
//   Cone         function select(dot(x - P, axis) - cos_cutoff d, 0, 1, 1):
//                1 where dot(x - P, axis) >= cos_cutoff d, else 0
//   Grey         `pigment_pattern { P }`: the grey value 0.297 r + 0.589 g +
//                0.114 b of the pigment tree P evaluated at the hit (with its
//                normal, so slope patterns inside P work), wrapped into
//                [0, 1) like a function's value (measured: 1.5 -> 0.5). The
//                trees built here keep it grey (r = g = b) and in [0, 1).
//                With exponent != 1, `poly_wave exponent` raises the wrapped
//                value v to v^exponent (POV-Ray's pow, after the wrap).
//   LightEye     function (1 + L.V) / 2, L = normalize(P - x), V =
//                normalize(E - x) (E = `eye`), its cosine clamped to [-1, 1]
//                inside the function, so the value stays in [0, 1]
struct PigmentNode;
struct Pattern {
  enum class Kind { Slope, Attenuation, Cone, Grey, LightEye };
  Kind kind = Kind::Slope;
  bool point_at = true;  // Slope: towards `point` (else along `direction`)
  glm::dvec3 point{0.0}, direction{0.0};  // the light's position; axis or D
  double c = 1, l = 0, q = 0;  // Attenuation
  double cos_cutoff = -1;      // Cone
  std::shared_ptr<const PigmentNode> inner;  // Grey
  double exponent = 1;         // Grey: poly_wave exponent when != 1
  glm::dvec3 eye{0.0};         // LightEye
};
// POV-Ray's grey value of a colour (the weights of `pigment_pattern`).
inline constexpr double kGreyRed = 0.297, kGreyGreen = 0.589, kGreyBlue = 0.114;
// The wave modifier that makes POV-Ray's slope value 0.5 + asin(N.L)/pi
// exactly (1 + N.L)/2: `sine_wave frequency kSlopeFrequency phase kSlopePhase`.
inline constexpr double kSlopeFrequency = -0.5, kSlopePhase = 0.75;
Pattern slopeTowards(glm::dvec3 point);
Pattern slopeAlong(glm::dvec3 direction);
Pattern attenuation(glm::dvec3 point, double c, double l, double q);
Pattern cone(glm::dvec3 point, glm::dvec3 axis, double cos_cutoff);
// The grey value of `inner` (a tree whose leaves are grey constants).
Pattern grey(std::shared_ptr<const PigmentNode> inner);
// grey(inner) raised to `exponent` (poly_wave).
Pattern greyPower(std::shared_ptr<const PigmentNode> inner, double exponent);
// (1 + L.V) / 2 at the hit for a light at `point` and the eye at `eye`.
Pattern lightEye(glm::dvec3 point, glm::dvec3 eye);
std::string patternSdl(const Pattern& p);

using Pigment = std::shared_ptr<const PigmentNode>;

struct PigmentNode {
  enum class Kind { Leaf, Map, Sum };
  Kind kind = Kind::Leaf;
  glm::dmat3 m{0.0};  // Leaf: out = m * C + b (glm is column-major: m[ch] is C.ch's column)
  glm::dvec3 b{0.0};
  Pattern pattern;  // Map
  std::vector<std::pair<double, Pigment>> entries;  // Map
  std::vector<Pigment> children;  // Sum
};

Pigment constant(glm::dvec3 c);
Pigment affine(glm::dmat3 m, glm::dvec3 b);  // m C + b
// Entries must be sorted by value in [0,1].
Pigment map(Pattern pattern, std::vector<std::pair<double, Pigment>> entries);
// v * p for a pattern value v in [0,1].
Pigment times(Pattern pattern, Pigment p);
Pigment sum(std::vector<Pigment> parts);
Pigment scaled(const Pigment& p, double k);
// The same tree with every leaf replaced by fn(leaf); the maps and sums
// stay. Since every node is linear in its leaves, this is how a factor is
// pushed into a tree (e.g. K -> C (x) K with leaves diag(k) C).
Pigment mapLeaves(const Pigment& p, const std::function<Pigment(const PigmentNode&)>& fn);

bool usesTexture(const Pigment& p);
// `texture_function`: the declared function of the texture's image_map that
// the leaves read (one per textured material of a scene).
std::string toSdl(const Pigment& p, int indent = 0, const std::string& texture_function = "XvalTexture");
// A leaf m C (b = 0) as a pigment with filter 1 everywhere: a layer of a
// layered texture whose layers below show through multiplied by m C per
// channel (POV-Ray multiplies them by filter x colour + transmit; measured
// exact, highlights included). Used for the texture colour C (m = I).
std::string filterLayerSdl(const PigmentNode& leaf, int indent = 0,
                           const std::string& texture_function = "XvalTexture");

}  // namespace xval::pov
