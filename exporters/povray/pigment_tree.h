// PigmentTree: a colour that POV-Ray computes exactly, built from blend maps.
//
// Every node is linear in its leaves, so constant factors and sums can be
// pushed down to the leaves:
//   Leaf:  out = M C + b   (C = the texture colour at the hit's uv, M 3x3)
//   Map:   a pattern value v in [0,1] and entries (v_i, node_i); POV-Ray
//          interpolates linearly between adjacent entries (pigment_map)
//   Sum:   sum of children (POV-Ray's `average` pigment_map, each child
//          scaled by the number of children)
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

struct PigmentNode;
using Pigment = std::shared_ptr<const PigmentNode>;

struct PigmentNode {
  enum class Kind { Leaf, Map, Sum };
  Kind kind = Kind::Leaf;
  glm::dmat3 m{0.0};  // Leaf: out = m * C + b (glm is column-major: m[ch] is C.ch's column)
  glm::dvec3 b{0.0};
  std::string pattern;  // Map
  std::vector<std::pair<double, Pigment>> entries;  // Map
  std::vector<Pigment> children;  // Sum
};

Pigment constant(glm::dvec3 c);
Pigment affine(glm::dmat3 m, glm::dvec3 b);  // m C + b
// Entries must be sorted by value in [0,1].
Pigment map(std::string pattern, std::vector<std::pair<double, Pigment>> entries);
// v * p for a pattern value v in [0,1].
Pigment times(std::string pattern, Pigment p);
Pigment sum(std::vector<Pigment> parts);
Pigment scaled(const Pigment& p, double k);
// The same tree with every leaf replaced by fn(leaf); the maps and sums
// stay. Since every node is linear in its leaves, this is how a factor is
// pushed into a tree (e.g. K -> C (x) K with leaves diag(k) C).
Pigment mapLeaves(const Pigment& p, const std::function<Pigment(const PigmentNode&)>& fn);

bool usesTexture(const Pigment& p);
std::string toSdl(const Pigment& p, int indent = 0);

}  // namespace xval::pov
