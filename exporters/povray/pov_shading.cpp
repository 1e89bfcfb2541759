#include "povray/pov_shading.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

#include "camera/camera.h"
#include "common/export_common.h"
#include "povray/sdl.h"
#include "shading/lights.h"
#include "shading/models.h"

namespace xval::pov {

using glm::dvec3;

std::string lightSourceSdl(const LightSource& l) {
  std::string s = "light_source { " + vec(l.location) + " rgb " + vec(l.colour);
  if (l.parallel) s += " parallel point_at <0, 0, 0>";
  if (l.fade_distance > 0)
    s += " fade_distance " + num(l.fade_distance) + " fade_power " + std::to_string(l.fade_power);
  if (l.spotlight)
    s += " spotlight point_at " + vec(l.point_at) + " radius " + num(l.cone_deg) + " falloff " +
         num(l.cone_deg) + " tightness 0";
  return s + " }";
}

namespace {


// (1 + N.L) / 2 for a light, exactly (docs/povray-export.md).
Pattern slopePattern(const Light& l) {
  if (auto* d = std::get_if<DirectionalLight>(&l)) return slopeAlong(-glm::normalize(d->direction));
  if (auto* p = std::get_if<PointLight>(&l)) return slopeTowards(p->position);
  return slopeTowards(std::get<SpotLight>(l).position);
}

struct LightInfo {
  const Light* light;
  dvec3 position{0.0}, colour{0.0};
  Attenuation att;
  bool has_att = false, spot = false, directional = false;
  dvec3 axis{0.0};
  double cutoff_deg = 0.0;
};

LightInfo info(const Light& l) {
  LightInfo i;
  i.light = &l;
  if (auto* p = std::get_if<PointLight>(&l)) {
    i.position = p->position, i.colour = p->color, i.att = p->attenuation;
  } else if (auto* s = std::get_if<SpotLight>(&l)) {
    i.position = s->position, i.colour = s->color, i.att = s->attenuation;
    i.spot = true, i.axis = glm::normalize(s->direction), i.cutoff_deg = s->cutoff_deg;
  } else if (auto* d = std::get_if<DirectionalLight>(&l)) {
    i.directional = true, i.colour = d->color, i.axis = glm::normalize(d->direction);
  }
  i.has_att = !i.directional && !i.att.isNone();
  return i;
}

// c / (c + l d + q d^2) in (0, 1]: the attenuation times c.
Pattern attPattern(const LightInfo& l) {
  return attenuation(l.position, l.att.constant, l.att.linear, l.att.quadratic);
}

// 1 inside the spot's cone (dot(p - p_light, axis) >= cos(cutoff) d), else 0.
Pattern conePattern(const LightInfo& l) {
  return cone(l.position, l.axis, std::cos(l.cutoff_deg * std::numbers::pi / 180.0));
}

// att (and the cone, when `with_cone`) times node.
Pigment perLight(const LightInfo& l, Pigment node, bool with_cone) {
  if (l.has_att) node = times(attPattern(l), scaled(node, 1.0 / l.att.constant));
  if (with_cone && l.spot) node = times(conePattern(l), node);
  return node;
}

// A pigment_map over (1 + N.L)/2 with the given (N.L, colour) breakpoints.
Pigment slopeMap(const Light& l, const std::vector<std::pair<double, dvec3>>& points) {
  std::vector<std::pair<double, Pigment>> e;
  for (const auto& [x, c] : points) e.emplace_back((1.0 + x) / 2.0, constant(c));
  return map(slopePattern(l), std::move(e));
}

// The Forsyth models and the diffuse part of classic Phong, per unit light
// colour, as (N.L, value) breakpoints: piecewise linear in between.
// One overload per model (a model without one does not compile): a model
// POV-Ray cannot express throws ExportError here.
std::vector<std::pair<double, dvec3>> diffuseBreakpoints(const LightingModel& model) {
  using P = std::vector<std::pair<double, dvec3>>;
  return std::visit(
      model::Overloaded{
          [](const ClassicPhong& m) { return P{{-1, dvec3(0)}, {0, dvec3(0)}, {1, dvec3(m.kd)}}; },
          [](const YiqLuma&) { return P{}; },  // its emission is emissionYiq's
          [](const Lambert& m) { return P{{-1, dvec3(0)}, {0, dvec3(0)}, {1, m.c0}}; },
          [](const WrapAround& m) { return P{{-1, dvec3(0)}, {-m.factor, dvec3(0)}, {1, m.c0}}; },
          [](const Hemispherical& m) { return P{{-1, m.c2}, {1, m.c0}}; },
          [](const BiDirectional& m) { return P{{-1, m.c2}, {0, dvec3(0)}, {1, m.c0}}; },
          [](const Trilight& m) { return P{{-1, m.c2}, {0, m.c1}, {1, m.c0}}; },
          // minnaert, blinn_phong, oren_nayar
          [](const Minnaert&) { return P{}; },  // not piecewise linear: minnaertTerm's
          [](const BlinnPhong& m) { return P{{-1, dvec3(0)}, {0, dvec3(0)}, {1, dvec3(m.kd)}}; },
          [](const OrenNayar&) -> P {
            throw ExportError(
                "oren_nayar: its term x (A + B t) divides L.V - (N.L)(N.V) by max(N.L, N.V), a quotient of "
                "two slope patterns; POV-Ray's pigments form only piecewise-linear maps, products and powers "
                "of pattern values in [0, 1) (pigment_pattern wraps 1 and above), so it cannot be expressed");
          },
          [](const CookTorrance& m) {
            // kd clamp(N.L); the microfacet term only when ks is 0.
            if (m.ks != 0.0)
              throw ExportError(
                  "cook_torrance with ks = " + num(m.ks) +
                  " (not 0): POV-Ray 3.7 cannot express its microfacet term S = pi F D G / (4 N.V), a "
                  "non-linear function of N.H, N.L, N.V and V.H together: its finishes have no microfacet D "
                  "or G (phong and specular are powers of one cosine), and its pigment maps compose one slope "
                  "pattern at a time (a product of two only as nested piecewise-bilinear maps, in single "
                  "precision), so D's exponential or GGX lobe and G / N.V would be piecewise-linear "
                  "approximations with an error of their own; ks = 0 (kd clamp(N.L) only) is expressible");
            return P{{-1, dvec3(0)}, {0, dvec3(0)}, {1, dvec3(m.kd)}};
          }},
      model);
}

// minnaert's term of one light (issue #33), per unit light colour times
// kd Lc: clamp(x)^k clamp(y)^(k-1), x = N.L, y = N.V. Each of clamp(x) and
// clamp(y) is a slope map scaled by 1/M (M = kMinnaertScale > 1, so the
// grey value stays below 1, where pigment_pattern does not wrap); poly_wave
// raises it to k and k - 1; the product is a map over the first power
// inside `times` of the second, its top entry kd Lc M^(2k - 1) undoing the
// scaling. Refused for k < 1: clamp(y)^(k-1) is unbounded (a grey value
// above 1 wraps).
inline constexpr double kMinnaertScale = 1.001;
Pigment minnaertTerm(const Light& l, dvec3 eye, const Minnaert& m, dvec3 colour) {
  if (m.k < 1.0)
    throw ExportError("minnaert: k = " + num(m.k) +
                      " < 1 makes clamp(N.V)^(k-1) unbounded towards the silhouette, which a POV-Ray pigment "
                      "value (a grey in [0, 1), wrapped above) cannot carry; k >= 1 is exported");
  const double M = kMinnaertScale;
  auto g = [](double v) { return constant(dvec3(v)); };
  const Pigment x = map(slopePattern(l), {{0.0, g(0.0)}, {0.5, g(0.0)}, {1.0, g(1.0 / M)}});
  Pigment term = map(greyPower(x, m.k), {{0.0, g(0.0)}, {1.0, constant(m.kd * colour * std::pow(M, 2.0 * m.k - 1.0))}});
  if (m.k == 1.0) return term;
  const Pigment y = map(slopeTowards(eye), {{0.0, g(0.0)}, {0.5, g(0.0)}, {1.0, g(1.0 / M)}});
  return times(greyPower(y, m.k - 1.0), term);
}

dvec3 ambientSum(const Scene& s) {
  dvec3 a(0.0);
  for (const auto& l : s.lights)
    if (auto* am = std::get_if<AmbientLight>(&l)) a += am->color;
  return a;
}

// Emission for classic Phong's ambient + diffuse and the Forsyth family:
// C (x) K with K = A' + sum_l [lit] att Lc (x) g(N.L) (+ course's per-light ka).
// With `filter_layer` the surface colour is left to the filter layer (C = 1 here).
Pigment emissionLinear(const Scene& s, const std::vector<LightInfo>& lights, bool filter_layer) {
  const LightingModel& model = s.material.model;
  dvec3 ambient = ambientSum(s);
  const auto* phong = std::get_if<ClassicPhong>(&model);
  const auto* blinn = std::get_if<BlinnPhong>(&model);
  const auto* minnaert = std::get_if<Minnaert>(&model);
  std::vector<Pigment> terms;
  terms.push_back(constant(phong ? phong->ka * ambient : blinn ? blinn->ka * ambient : ambient));
  auto points = diffuseBreakpoints(model);
  for (const auto& l : lights) {
    if (minnaert) {
      terms.push_back(perLight(l, minnaertTerm(*l.light, CameraRays(s.camera).origin, *minnaert, l.colour), true));
      continue;
    }
    auto scaled_points = points;
    for (auto& p : scaled_points) p.second *= l.colour;
    terms.push_back(perLight(l, slopeMap(*l.light, scaled_points), true));
    if (phong && phong->variant == ClassicPhong::Variant::Course && phong->ka != 0.0)
      terms.push_back(perLight(l, constant(phong->ka * l.colour), false));
  }
  Pigment k = sum(std::move(terms));
  // Multiply by the surface colour C at the leaves.
  const bool textured = s.material.texture.has_value() && !filter_layer;
  const dvec3 base = filter_layer ? dvec3(1.0) : s.material.base_color;
  return mapLeaves(k, [&](const PigmentNode& leaf) {
    return textured ? affine(glm::dmat3(leaf.b.x, 0, 0, 0, leaf.b.y, 0, 0, 0, leaf.b.z), dvec3(0.0))
                    : constant(base * leaf.b);
  });
}

// The YIQ emission where Dl = saturate(s), s = A_Y + kd sum_l [lit] att_l
// Y(Lc_l) sat(N.L_l), can reach 1 with several or attenuated lights: s is
// a sum of per-light terms, computed as a grey pigment scaled by 1/M
// (M = 1.001 smax > smax = A_Y + kd sum_l Y(Lc_l)/c_l >= s, so the grey
// value s/M stays in [0, 1), where pigment_pattern does not wrap), and a
// pigment_map over that value with a knee at 1/M is leaf(Dl - 1):
//   v = 0: leaf(-1),  v = 1/M: leaf(0) (Dl = M v reaches 1),  v = 1: leaf(0).
template <class Leaf>
Pigment emissionYiqSaturated(const Scene& s, const std::vector<LightInfo>& lights, double a,
                             double wsum, const Leaf& leaf) {
  const auto& m = std::get<YiqLuma>(s.material.model);
  if (a < 0.0 || m.kd < 0.0)
    throw ExportError("yiq_luma: a negative ambient luma or kd makes the sum under Dl's saturate "
                      "negative, which POV-Ray's pigment_pattern would wrap");
  for (const auto& l : lights)
    if (models::lightLuma(l.colour) < 0.0)
      throw ExportError("yiq_luma: a light of negative luma makes the sum under Dl's saturate "
                        "negative, which POV-Ray's pigment_pattern would wrap");
  const double big_m = 1.001 * (a + wsum);
  std::vector<Pigment> terms{constant(dvec3(a / big_m))};
  for (const auto& l : lights) {
    const double wl = m.kd * models::lightLuma(l.colour) / big_m;
    terms.push_back(perLight(l, slopeMap(*l.light, {{-1, dvec3(0)}, {0, dvec3(0)}, {1, dvec3(wl)}}), true));
  }
  return map(grey(sum(std::move(terms))), {{0.0, leaf(-1.0)}, {1.0 / big_m, leaf(0.0)}, {1.0, leaf(0.0)}});
}

// Emission for the YIQ model without its specular term:
//   C - off + Y (Dl - 1) (1,1,1).
Pigment emissionYiq(const Scene& s, const std::vector<LightInfo>& lights) {
  const auto& m = std::get<YiqLuma>(s.material.model);
  const double a = models::lightLuma(ambientSum(s));
  const dvec3 w(models::kRgbToYiq[0][0], models::kRgbToYiq[0][1], models::kRgbToYiq[0][2]);
  const bool textured = s.material.texture.has_value();
  const dvec3 base = s.material.base_color;
  // Leaf for a given value of (Dl - 1): C - off + Y k (1,1,1) = (I + k 1 w^T) C - off.
  auto leaf = [&](double k) {
    glm::dmat3 mm(1.0);
    for (int ch = 0; ch < 3; ++ch) mm[ch] += dvec3(k * w[ch]);
    dvec3 off(-m.luma_offset);
    return textured ? affine(mm, off) : constant(mm * base + off);
  };
  double wsum = 0.0;
  for (const auto& l : lights) wsum += m.kd * models::lightLuma(l.colour) / (l.has_att ? l.att.constant : 1.0);
  if (a + wsum <= 1.0) {
    // Dl never clips: Dl - 1 = (A - 1) + sum_l [lit] att w_l sat(N.L), linear in each light.
    std::vector<Pigment> terms{leaf(a - 1.0)};
    for (const auto& l : lights) {
      double wl = m.kd * models::lightLuma(l.colour);
      auto per = map(slopePattern(*l.light),
                     {{0.0, constant(dvec3(0))}, {0.5, constant(dvec3(0))}, {1.0, constant(dvec3(wl))}});
      // Turn the scalar k (stored in b.x) into the leaf's C-dependent part.
      Pigment lp = mapLeaves(per, [&](const PigmentNode& n) {
        glm::dmat3 mm(0.0);
        for (int ch = 0; ch < 3; ++ch) mm[ch] = dvec3(n.b.x * w[ch]);
        return textured ? affine(mm, dvec3(0.0)) : constant(mm * base);
      });
      terms.push_back(perLight(l, lp, true));
    }
    return sum(std::move(terms));
  }
  if (lights.size() != 1 || lights[0].has_att) return emissionYiqSaturated(s, lights, a, wsum, leaf);
  const LightInfo& l = lights[0];
  const double wl = m.kd * models::lightLuma(l.colour);
  auto dl = [&](double x) { return std::min(1.0, a + wl * std::clamp(x, 0.0, 1.0)); };
  std::vector<std::pair<double, Pigment>> e;
  e.emplace_back(0.0, leaf(dl(-1) - 1));
  e.emplace_back(0.5, leaf(dl(0) - 1));
  double xk = wl > 0 ? (1.0 - a) / wl : 2.0;  // where Dl reaches 1
  if (xk > 0.0 && xk < 1.0) e.emplace_back((1.0 + xk) / 2.0, leaf(0.0));
  e.emplace_back(1.0, leaf(dl(1) - 1));
  Pigment lit = map(slopePattern(*l.light), std::move(e));
  if (!l.spot) return lit;
  return map(conePattern(l), {{0.0, leaf(std::min(1.0, a) - 1.0)}, {1.0, lit}});
}

// Real roots 0 < r1 < r2 of c + l d + q d^2 = q (d + r1)(d + r2), when the
// two differ by at least a quarter of r2 (else the two terms below cancel:
// each is (d + r2)/(r2 - r1) times their difference, and POV-Ray sums them
// in single precision).
std::optional<std::pair<double, double>> realRoots(const Attenuation& a) {
  const double disc = a.linear * a.linear - 4.0 * a.quadratic * a.constant;
  if (!(disc > 0.0) || a.quadratic <= 0.0) return std::nullopt;
  const double root = std::sqrt(disc);
  const double r1 = (a.linear - root) / (2.0 * a.quadratic), r2 = (a.linear + root) / (2.0 * a.quadratic);
  if (!(r1 > 0.0) || r2 - r1 < 0.25 * r2) return std::nullopt;
  return std::pair{r1, r2};
}

// The specular term of one light as an emission pigment, for an
// attenuation that no sum of POV-Ray light sources gives (complex roots,
// among several lights): ks colour att [lit] clamp(R.V)^n with
//   R.V = 2 (N.L)(N.V) - L.V = 2 (2a - 1)(2b - 1) + 1 - 2e,
// a = (1 + N.L)/2 and b = (1 + N.V)/2 slope patterns (towards the light and
// the eye), e = (1 + L.V)/2 a function of position. The nested maps:
//   G = 0.5 + h R.V in [0.5 - h, 0.5 + h] (grey; the bilinear term is a map
//       over a of maps over b, exact at the corners a, b in {0, 1}; h =
//       kHighlightHalfRange < 1/2, so G stays inside (0, 1) and
//       pigment_pattern does not wrap);
//   T = k clamp(R.V) = k clamp((G - 0.5)/h) in [0, k]: a map over G with a
//       knee at 0.5 (k = kHighlightScale < 1: T does not reach 1 either);
//   T^n by `poly_wave n` on pigment_pattern { T }, and a map over it from 0
//       to ks colour / k^n.
//   (k = max(kHighlightScale, 1 - 1/(4n)) keeps 1/k^n below e^(1/4)/0.998^125
//   ~ 1.6 at any n, so the last entry stays finite.)
// POV-Ray computes these pigments in single precision: R.V carries an
// absolute error of a few 1e-7, which S = R.V^n multiplies by about n, so
// the exporter refuses a highlight whose weight n ks max(colour)/c exceeds
// kMaxHighlightWeight (docs/povray-export.md: at most 1.57/65535 measured
// at weight 180, 2.88 at 360, the default tolerance being 2).
inline constexpr double kHighlightHalfRange = 0.499, kHighlightScale = 0.998;
inline constexpr double kMaxHighlightWeight = 200;

Pigment highlight(const LightInfo& l, dvec3 eye, double ks, double shininess, dvec3 colour) {
  const double weight = shininess * ks * std::max({colour.x, colour.y, colour.z}) / l.att.constant;
  if (weight > kMaxHighlightWeight)
    throw ExportError(
        "attenuation 1/(c + l d + q d^2) with l > 0, q > 0 and l^2 < 4 q c (or nearly equal roots) on a light "
        "with a specular highlight, among several lights, with shininess x ks x light colour / c = " +
        num(weight) + " above " + num(kMaxHighlightWeight) +
        ": that highlight is computed in POV-Ray's single-precision pigments (no sum of fades has the "
        "complex poles), whose error grows with the shininess (2.9/65535 measured at 360)");
  const double h = kHighlightHalfRange, k = std::max(kHighlightScale, 1.0 - 0.25 / std::max(shininess, 1.0));
  auto g = [](double v) { return constant(dvec3(v)); };
  const Pattern a = slopeTowards(l.position), b = slopeTowards(eye);
  Pigment rv = sum({g(0.5), map(a, {{0.0, map(b, {{0.0, g(2 * h)}, {1.0, g(-2 * h)}})},
                                    {1.0, map(b, {{0.0, g(-2 * h)}, {1.0, g(2 * h)}})}}),
                    map(lightEye(l.position, eye), {{0.0, g(h)}, {1.0, g(-h)}})});
  // At G = 1 the line through (0.5, 0) and (0.5 + h, k) reaches k / (2h).
  Pigment clamped = map(grey(rv), {{0.0, g(0.0)}, {0.5, g(0.0)}, {1.0, g(k / (2.0 * h))}});
  Pigment s = map(greyPower(clamped, shininess),
                  {{0.0, g(0.0)}, {1.0, constant(ks * colour / std::pow(k, shininess))}});
  return perLight(l, s, true);
}

// The light source of l with colour `colour`, without its attenuation:
// parallel, or at l's position (a hard-edged spotlight for a spot).
LightSource sourceOf(const LightInfo& l, dvec3 colour) {
  LightSource src;
  src.colour = colour;
  if (l.directional) {
    src.location = -l.axis;
    src.parallel = true;
    return src;
  }
  src.location = l.position;
  if (l.spot) {
    src.spotlight = true;
    src.point_at = l.position + l.axis;
    src.cone_deg = l.cutoff_deg;
  }
  return src;
}

// The specular term: POV-Ray's phong through light sources, and for the
// lights whose attenuation no light source gives, `highlights` (emission
// terms, see highlight()).
Specular specular(const Scene& s, const std::vector<LightInfo>& lights, bool filter_layer,
                  std::vector<Pigment>& highlights) {
  Specular sp;
  const LightingModel& model = s.material.model;
  std::function<dvec3(const LightInfo&)> colour;
  if (auto* m = std::get_if<ClassicPhong>(&model)) {
    sp.ks = m->ks, sp.shininess = m->shininess;
    if (m->variant == ClassicPhong::Variant::Course) {
      // C (x) Lc ks S: the base colour in the light colour, or the texture
      // colour from the filter layer above.
      colour = [&s, filter_layer](const LightInfo& l) {
        return filter_layer ? l.colour : l.colour * s.material.base_color;
      };
    } else {
      colour = [](const LightInfo& l) { return l.colour; };
    }
  } else if (auto* m = std::get_if<YiqLuma>(&model)) {
    sp.ks = m->ks, sp.shininess = m->shininess;
    colour = [](const LightInfo& l) { return dvec3(models::lightLuma(l.colour)); };
  } else if (auto* m = std::get_if<BlinnPhong>(&model)) {  // issue #33: POV-Ray's `specular`
    sp.ks = m->ks, sp.shininess = m->shininess, sp.blinn = true;
    if (m->ks != 0.0 && !(m->shininess > 0.0))
      throw ExportError("blinn_phong: shininess " + num(m->shininess) +
                        " is exported as POV-Ray's `specular ks roughness 1/n`, which needs n > 0");
    colour = [](const LightInfo& l) { return l.colour; };
  }
  if (sp.ks == 0.0) return sp;
  // 1/(c + l d + q d^2) with l > 0 and q > 0 and no real roots apart: a
  // texture_map over its position function for a single light (it scales
  // every highlight), else that light's highlight in the emission tree.
  auto general = [](const LightInfo& l) {
    return l.has_att && l.att.linear != 0.0 && l.att.quadratic != 0.0 && !realRoots(l.att);
  };
  const dvec3 eye = CameraRays(s.camera).origin;
  for (const auto& l : lights) {
    if (lights.size() > 1 && general(l) && sp.blinn)
      throw ExportError("blinn_phong: attenuation 1/(c + l d + q d^2) with l > 0, q > 0 and l^2 < 4 q c (or "
                        "nearly equal roots) on a light with a highlight, among several lights: no sum of POV-Ray "
                        "light sources gives it, and the emission-pigment highlight is classic Phong's R.V");
    if (lights.size() > 1 && general(l)) {
      highlights.push_back(highlight(l, eye, sp.ks, sp.shininess, colour(l)));
      continue;
    }
    if (lights.size() == 1 && l.has_att && l.att.linear != 0.0 && l.att.quadratic != 0.0) {
      // The texture_map over the attenuation function: the light source
      // carries 1/c.
      LightSource src = sourceOf(l, colour(l) / l.att.constant);
      sp.att_texture_map = attPattern(l);
      sp.light_sources.push_back(src);
      continue;
    }
    // Only the general case above has no light sources (realRoots).
    const std::vector<LightSource> sources = *lightSourcesOf(*l.light, colour(l));
    sp.light_sources.insert(sp.light_sources.end(), sources.begin(), sources.end());
  }
  return sp;
}

// The luma-only mode, yiq (colour/luma_only.h): with the grey lights and
// C = 1 the model's emission tree (emissionLinear) is the lit grey factor
// K, and every leaf's luma k gives the rank-one leaf k Y_C (1,1,1) (Y_C =
// w . C, the listing's row); one more term C - Y_C (1,1,1) makes
//   F = C + (Y_C K_Y - Y_C)(1,1,1), K_Y = Y(K),
// which is the mode's C + (Y_out - Y_C)(1,1,1) for the models whose result
// is C (x) K (+ a highlight independent of C: POV-Ray's phong with the grey
// light sources adds ks S Y(Lc) (1,1,1), its luma). Refused: cie_lstar
// (below), yiq_luma (its Dl's saturate of Y_C's factor: emissionYiq is
// written for a coloured C with its own leaves) and classic_phong course
// with a highlight (C (x) Lc ks S: its highlight scales with C).
Pigment emissionLumaOnlyYiq(const Scene& grey, const std::vector<LightInfo>& lights) {
  const dvec3 w(models::kRgbToYiq[0][0], models::kRgbToYiq[0][1], models::kRgbToYiq[0][2]);
  const bool textured = grey.material.texture.has_value();
  const dvec3 base = grey.material.base_color;
  auto luma_leaf = [&](double k) {  // k Y_C (1,1,1)
    glm::dmat3 mm(0.0);
    for (int ch = 0; ch < 3; ++ch) mm[ch] = dvec3(k * w[ch]);
    return textured ? affine(mm, dvec3(0.0)) : constant(mm * base);
  };
  Pigment k = mapLeaves(emissionLinear(grey, lights, true), [&](const PigmentNode& leaf) {
    return luma_leaf(luma_only::lightLuma(LumaSpace::Yiq, leaf.b));
  });
  return sum({k, textured ? [&] {
    glm::dmat3 mm(1.0);
    for (int ch = 0; ch < 3; ++ch) mm[ch] -= dvec3(w[ch]);
    return affine(mm, dvec3(0.0));
  }()
                          : constant(base - dvec3(glm::dot(w, base)))});
}

void checkLumaOnlyExpressible(const Material& m) {
  if (!m.luma_only) return;
  if (*m.luma_only == LumaSpace::CieLstar)
    throw ExportError(
        "luma_only cie_lstar is not expressible: its colour f^-1(f(t_C) + f(Y_out) - f(Y_C)) per XYZ channel "
        "combines the texture colour and the lit luma through cube roots and cubes, and the POV-Ray export's "
        "pigment trees are sums of maps over patterns with leaves affine in C (a function pigment has pow but "
        "no surface normal, on which Y_out depends)");
  if (std::holds_alternative<YiqLuma>(m.model))
    throw ExportError("luma_only yiq with the yiq_luma model is not expressible: the POV-Ray export writes "
                      "yiq_luma's saturated Dl for the coloured surface colour only");
  if (auto* p = std::get_if<ClassicPhong>(&m.model); p && p->variant == ClassicPhong::Variant::Course && p->ks != 0.0)
    throw ExportError("luma_only yiq with classic_phong course and ks > 0 is not expressible: its highlight "
                      "Y_C Y(Lc) ks S scales with the surface colour's luma, which POV-Ray's phong cannot");
}

}  // namespace

std::optional<std::vector<LightSource>> lightSourcesOf(const Light& light, dvec3 colour) {
  const LightInfo l = info(light);
  LightSource src = sourceOf(l, colour);
  if (!l.has_att) return std::vector<LightSource>{src};
  const double c = l.att.constant, lin = l.att.linear, q = l.att.quadratic;
  if (lin != 0.0 && q != 0.0) {
    const auto roots = realRoots(l.att);
    if (!roots) return std::nullopt;
    // 1/(q (d + r1)(d + r2)) = (1/(d + r1) - 1/(d + r2)) / (q (r2 - r1)),
    // 1/(d + r) = (2/(1 + d/r)) / (2 r): two lights of fade_power 1, the
    // second of negative colour.
    const auto [r1, r2] = *roots;
    const double k = 1.0 / (q * (r2 - r1));
    LightSource far = src;
    src.colour *= k / (2.0 * r1), src.fade_distance = r1, src.fade_power = 1;
    far.colour *= -k / (2.0 * r2), far.fade_distance = r2, far.fade_power = 1;
    return std::vector<LightSource>{src, far};
  }
  if (lin != 0.0) {
    // 2/(1 + d/fd) with fd = c/l is 2c/(c + l d).
    src.colour /= 2.0 * c;
    src.fade_distance = c / lin, src.fade_power = 1;
  } else if (q != 0.0) {
    // 2/(1 + (d/fd)^2) with fd = sqrt(c/q) is 2c/(c + q d^2).
    src.colour /= 2.0 * c;
    src.fade_distance = std::sqrt(c / q), src.fade_power = 2;
  } else {
    src.colour /= c;
  }
  return std::vector<LightSource>{src};
}

PovShading povShading(const Scene& in) {
  // The luma-only mode shades with the grey lights (emissionLumaOnlyYiq).
  checkLumaOnlyExpressible(in.material);
  Scene grey;
  if (in.material.luma_only) {
    grey = in;
    grey.lights = greyLights(in.lights, *in.material.luma_only);
  }
  const Scene& scene = in.material.luma_only ? grey : in;
  std::vector<LightInfo> lights;
  for (const auto& l : scene.lights)
    if (!std::holds_alternative<AmbientLight>(l)) lights.push_back(info(l));
  PovShading p;
  // Classic Phong's course variant multiplies its highlight by C too: with a
  // texture and ks > 0 that per-channel product is the filter layer's.
  const auto* phong = std::get_if<ClassicPhong>(&scene.material.model);
  p.texture_filter_layer = phong && phong->variant == ClassicPhong::Variant::Course &&
                           phong->ks != 0.0 && scene.material.texture.has_value();
  p.emission = scene.material.luma_only                            ? emissionLumaOnlyYiq(scene, lights)
               : std::holds_alternative<YiqLuma>(scene.material.model) ? emissionYiq(scene, lights)
                                                                    : emissionLinear(scene, lights, p.texture_filter_layer);
  std::vector<Pigment> highlights;
  p.specular = specular(scene, lights, p.texture_filter_layer, highlights);
  if (!highlights.empty()) {
    highlights.insert(highlights.begin(), p.emission);
    p.emission = sum(std::move(highlights));
  }
  return p;
}

PovShading povShading(const Scene& scene, const Material& material) {
  Scene s = scene;
  s.material = material;
  return povShading(s);
}

}  // namespace xval::pov
