#include "povray/pigment_tree.h"

#include <functional>

#include "povray/sdl.h"

namespace xval::pov {

Pattern slopeTowards(glm::dvec3 point) {
  Pattern p;
  p.kind = Pattern::Kind::Slope, p.point_at = true, p.point = point;
  return p;
}
Pattern slopeAlong(glm::dvec3 direction) {
  Pattern p;
  p.kind = Pattern::Kind::Slope, p.point_at = false, p.direction = direction;
  return p;
}
Pattern attenuation(glm::dvec3 point, double c, double l, double q) {
  Pattern p;
  p.kind = Pattern::Kind::Attenuation, p.point = point, p.c = c, p.l = l, p.q = q;
  return p;
}
Pattern cone(glm::dvec3 point, glm::dvec3 axis, double cos_cutoff) {
  Pattern p;
  p.kind = Pattern::Kind::Cone, p.point = point, p.direction = axis, p.cos_cutoff = cos_cutoff;
  return p;
}

Pattern grey(std::shared_ptr<const PigmentNode> inner) {
  Pattern p;
  p.kind = Pattern::Kind::Grey, p.inner = std::move(inner);
  return p;
}

Pattern greyPower(std::shared_ptr<const PigmentNode> inner, double exponent) {
  Pattern p = grey(std::move(inner));
  p.exponent = exponent;
  return p;
}

Pattern lightEye(glm::dvec3 point, glm::dvec3 eye) {
  Pattern p;
  p.kind = Pattern::Kind::LightEye, p.point = point, p.eye = eye;
  return p;
}

namespace {

std::string bodySdl(const Pigment& p, int ind, const std::string& fn);

std::string distanceExpr(glm::dvec3 p) {
  return "sqrt((x - " + num(p.x) + ")*(x - " + num(p.x) + ") + (y - " + num(p.y) + ")*(y - " +
         num(p.y) + ") + (z - " + num(p.z) + ")*(z - " + num(p.z) + "))";
}

}  // namespace

std::string patternSdl(const Pattern& p) {
  switch (p.kind) {
    case Pattern::Kind::Slope:
      return (p.point_at ? "slope { point_at " + vec(p.point) + " }" : "slope { " + vec(p.direction) + " }") +
             " sine_wave frequency " + num(kSlopeFrequency) + " phase " + num(kSlopePhase);
    case Pattern::Kind::Attenuation: {
      const std::string d = distanceExpr(p.point);
      return "function { " + num(p.c) + " / (" + num(p.c) + " + " + num(p.l) + " * " + d + " + " +
             num(p.q) + " * " + d + " * " + d + ") }";
    }
    case Pattern::Kind::Cone: {
      const glm::dvec3 x = p.point, a = p.direction;
      return "function { select((x - " + num(x.x) + ") * " + num(a.x) + " + (y - " + num(x.y) +
             ") * " + num(a.y) + " + (z - " + num(x.z) + ") * " + num(a.z) + " - " +
             num(p.cos_cutoff) + " * " + distanceExpr(x) + ", 0, 1, 1) }";
    }
    case Pattern::Kind::Grey:  // its leaves are grey constants: no texture lookup (leafSdl checks)
      return "pigment_pattern {\n" + bodySdl(p.inner, 1, "") + "\n}" +
             (p.exponent != 1.0 ? " poly_wave " + num(p.exponent) : "");
    case Pattern::Kind::LightEye: {
      // dot(P - x, E - x) / (|P - x| |E - x|), clamped to [-1, 1].
      const glm::dvec3 l = p.point, e = p.eye;
      const std::string dot = "((" + num(l.x) + " - x)*(" + num(e.x) + " - x) + (" + num(l.y) + " - y)*(" +
                              num(e.y) + " - y) + (" + num(l.z) + " - z)*(" + num(e.z) + " - z))";
      return "function { 0.5 + 0.5 * min(1, max(-1, " + dot + " / (" + distanceExpr(l) + " * " +
             distanceExpr(e) + "))) }";
    }
  }
  return "";
}

Pigment constant(glm::dvec3 c) { return affine(glm::dmat3(0.0), c); }

Pigment affine(glm::dmat3 m, glm::dvec3 b) {
  auto n = std::make_shared<PigmentNode>();
  n->kind = PigmentNode::Kind::Leaf;
  n->m = m;
  n->b = b;
  return n;
}

Pigment map(Pattern pattern, std::vector<std::pair<double, Pigment>> entries) {
  auto n = std::make_shared<PigmentNode>();
  n->kind = PigmentNode::Kind::Map;
  n->pattern = std::move(pattern);
  n->entries = std::move(entries);
  return n;
}

Pigment times(Pattern pattern, Pigment p) {
  return map(std::move(pattern), {{0.0, constant(glm::dvec3(0.0))}, {1.0, std::move(p)}});
}

Pigment sum(std::vector<Pigment> parts) {
  if (parts.size() == 1) return parts[0];
  auto n = std::make_shared<PigmentNode>();
  n->kind = PigmentNode::Kind::Sum;
  n->children = std::move(parts);
  return n;
}

Pigment mapLeaves(const Pigment& p, const std::function<Pigment(const PigmentNode&)>& fn) {
  switch (p->kind) {
    case PigmentNode::Kind::Leaf: return fn(*p);
    case PigmentNode::Kind::Map: {
      std::vector<std::pair<double, Pigment>> e;
      for (const auto& [v, c] : p->entries) e.emplace_back(v, mapLeaves(c, fn));
      return map(p->pattern, std::move(e));
    }
    case PigmentNode::Kind::Sum: {
      std::vector<Pigment> c;
      for (const auto& ch : p->children) c.push_back(mapLeaves(ch, fn));
      return sum(std::move(c));
    }
  }
  return p;
}

Pigment scaled(const Pigment& p, double k) {
  return mapLeaves(p, [k](const PigmentNode& l) { return affine(l.m * k, l.b * k); });
}

bool usesTexture(const Pigment& p) {
  switch (p->kind) {
    case PigmentNode::Kind::Leaf: return p->m != glm::dmat3(0.0);
    case PigmentNode::Kind::Map:
      for (const auto& e : p->entries)
        if (usesTexture(e.second)) return true;
      return false;
    case PigmentNode::Kind::Sum:
      for (const auto& c : p->children)
        if (usesTexture(c)) return true;
      return false;
  }
  return false;
}

namespace {

std::string pad(int n) { return std::string(size_t(n) * 2, ' '); }

// out = sum_ch C.ch m[ch] + b: an average of n parts, each carrying n
// times its term, so that the average is the sum.
// With `filter`, every colour is rgbf with filter 1 (the average keeps it 1).
std::string leafSdl(const PigmentNode& l, int ind, const std::string& fn, bool filter = false) {
  static const char* channel[3] = {"red", "green", "blue"};
  auto colour = [filter](glm::dvec3 c) {
    return filter ? "rgbf <" + num(c.x) + ", " + num(c.y) + ", " + num(c.z) + ", 1>" : "rgb " + vec(c);
  };
  int n = l.b != glm::dvec3(0.0) ? 1 : 0;
  for (int ch = 0; ch < 3; ++ch) n += l.m[ch] != glm::dvec3(0.0) ? 1 : 0;
  if (n == 0 || (n == 1 && l.b != glm::dvec3(0.0))) return pad(ind) + colour(l.b);
  std::vector<std::string> parts;
  for (int ch = 0; ch < 3; ++ch) {
    glm::dvec3 col = l.m[ch];
    if (col == glm::dvec3(0.0)) continue;
    if (fn.empty())  // a texture term where no texture function is in scope (inside a grey pattern)
      throw std::logic_error("pigment tree: a texture-dependent leaf inside a grey pigment_pattern");
    // C.ch in [0,1] is the pattern value; the colour_map scales it.
    parts.push_back("uv_mapping function { " + fn + "(x, y, z)." + std::string(channel[ch]) +
                    " } colour_map { [0 " + colour(glm::dvec3(0.0)) + "] [1 " + colour(col * double(n)) + "] }");
  }
  if (l.b != glm::dvec3(0.0)) parts.push_back(colour(l.b * double(n)));
  if (n == 1) return pad(ind) + parts[0];
  std::string s = pad(ind) + "average pigment_map {\n";
  for (const auto& part : parts) s += pad(ind + 1) + "[1 " + part + "]\n";
  return s + pad(ind) + "}";
}

// A pigment body (what goes inside `pigment { }` or a pigment_map entry).
std::string bodySdl(const Pigment& p, int ind, const std::string& fn) {
  switch (p->kind) {
    case PigmentNode::Kind::Leaf: return leafSdl(*p, ind, fn);
    case PigmentNode::Kind::Map: {
      std::string s = pad(ind) + patternSdl(p->pattern) + "\n" + pad(ind) + "pigment_map {\n";
      for (const auto& [v, c] : p->entries)
        s += pad(ind + 1) + "[" + num(v) + "\n" + bodySdl(c, ind + 2, fn) + "]\n";
      return s + pad(ind) + "}";
    }
    case PigmentNode::Kind::Sum: {
      const double n = double(p->children.size());
      std::string s = pad(ind) + "average pigment_map {\n";
      for (const auto& c : p->children)
        s += pad(ind + 1) + "[1\n" + bodySdl(scaled(c, n), ind + 2, fn) + "]\n";
      return s + pad(ind) + "}";
    }
  }
  return "";
}

}  // namespace

std::string toSdl(const Pigment& p, int ind, const std::string& fn) {
  return pad(ind) + "pigment {\n" + bodySdl(p, ind + 1, fn) + "\n" + pad(ind) + "}";
}

std::string filterLayerSdl(const PigmentNode& leaf, int ind, const std::string& fn) {
  return pad(ind) + "pigment {\n" + leafSdl(leaf, ind + 1, fn, true) + "\n" + pad(ind) + "}";
}

}  // namespace xval::pov
