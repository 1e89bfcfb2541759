#include "scene_file/precision_limits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include <fmt/format.h>

#include "geometry/model_file.h"
#include "geometry/transform.h"
#include "scene/json_reader.h"
#include "scene/scene_limits.h"

namespace xval {

namespace {

// Six significant digits, as the reports' numbers (text/number_text.h significant).
std::string num(double v) { return fmt::format("{:.6g}", v); }

// Every number of the scene that a renderer computes with, with its field
// path as in the scene file and whether it is a coordinate or length of the
// camera or an object. (Integers are exact in both precisions and bounded
// by the loader; the tolerances are not rendered.)
enum class Kind { Coordinate, UvRepeat, Number };
using Visit = std::function<void(const std::string& path, double value, Kind kind)>;

void vec(const Visit& f, const std::string& path, const glm::dvec3& v, Kind kind) {
  for (int i = 0; i < 3; ++i) f(path + "[" + std::to_string(i) + "]", v[i], kind);
}
void vec(const Visit& f, const std::string& path, const glm::dvec2& v, Kind kind) {
  for (int i = 0; i < 2; ++i) f(path + "[" + std::to_string(i) + "]", v[i], kind);
}

void attenuation(const Visit& f, const std::string& at, const Attenuation& a) {
  f(at + ".attenuation.constant", a.constant, Kind::Number);
  f(at + ".attenuation.linear", a.linear, Kind::Number);
  f(at + ".attenuation.quadratic", a.quadratic, Kind::Number);
}

// A material's numbers, under `prefix` ("material", "objects[2].material").
void materialNumbers(const Visit& f, const std::string& prefix, const Material& mat) {
  const std::string m = prefix + ".model";
  std::visit(
      [&]<class M>(const M& mm) {
        model::forEachParam(mm, model::Overloaded{
                                    [&](const model::NumberParam<M>& p, double v) {
                                      f(m + "." + p.name, v, Kind::Number);
                                    },
                                    [&](const model::ColourParam<M>& p, const glm::dvec3& v) {
                                      vec(f, m + "." + p.name, v, Kind::Number);
                                    },
                                    [](const auto&, const auto&) {}});  // a choice: no number
      },
      mat.model);
  if (!mat.texture || mat.texture->source == TextureSpec::Source::Model)
    vec(f, prefix + ".base_color", mat.base_color, Kind::Number);
}

void forEachNumber(const Scene& s, const Visit& f) {
  vec(f, "camera.position", s.camera.position, Kind::Coordinate);
  vec(f, "camera.target", s.camera.target, Kind::Coordinate);
  vec(f, "camera.up", s.camera.up, Kind::Number);
  f("camera.fov_y_deg", s.camera.fov_y_deg, Kind::Number);
  for (size_t k = 0; k < s.objects.size(); ++k) {
    const std::string at = "objects[" + std::to_string(k) + "]";
    if (const auto* t = std::get_if<TorusKnot>(&s.objects[k].shape)) {
      f(at + ".major_radius", t->major_radius, Kind::Coordinate);
      f(at + ".minor_radius", t->minor_radius, Kind::Coordinate);
      f(at + ".tube_radius", t->tube_radius, Kind::Coordinate);
      vec(f, at + ".uv_repeat", t->uv_repeat, Kind::UvRepeat);
      vec(f, at + ".center", t->center, Kind::Coordinate);
    } else if (const auto* u = std::get_if<UvSphere>(&s.objects[k].shape)) {
      vec(f, at + ".center", u->center, Kind::Coordinate);
      f(at + ".radius", u->radius, Kind::Coordinate);
      vec(f, at + ".uv_repeat", u->uv_repeat, Kind::UvRepeat);
    } else if (const auto* p = std::get_if<Plane>(&s.objects[k].shape)) {
      vec(f, at + ".center", p->center, Kind::Coordinate);
      vec(f, at + ".normal", p->normal, Kind::Number);
      vec(f, at + ".size", p->size, Kind::Coordinate);
      vec(f, at + ".uv_repeat", p->uv_repeat, Kind::UvRepeat);
    } else if (const auto* mf = std::get_if<MeshFile>(&s.objects[k].shape)) {
      // The file's largest coordinate once placed by the object's transform.
      const Affine a = toAffine(s.objects[k].transform);
      double largest = 0.0;
      for (const auto& prim : mf->model->primitives)
        for (const auto& v : prim.mesh.positions) {
          const glm::dvec3 w = a.point(v);
          largest = std::max({largest, std::abs(w.x), std::abs(w.y), std::abs(w.z)});
        }
      f(at + ".path", largest, Kind::Coordinate);
    }
    const ObjectTransform& tr = s.objects[k].transform;
    vec(f, at + ".transform.scale", tr.scale, Kind::Coordinate);
    vec(f, at + ".transform.rotate.axis", tr.rotate.axis, Kind::Number);
    f(at + ".transform.rotate.angle_deg", tr.rotate.angle_deg, Kind::Number);
    vec(f, at + ".transform.translate", tr.translate, Kind::Coordinate);
    if (s.objects[k].material) materialNumbers(f, at + ".material", *s.objects[k].material);
  }
  materialNumbers(f, "material", s.material);

  for (size_t k = 0; k < s.lights.size(); ++k) {
    const std::string at = "lights[" + std::to_string(k) + "]";
    std::visit(
        [&](const auto& l) {
          using L = std::decay_t<decltype(l)>;
          if constexpr (std::is_same_v<L, PointLight>) {
            vec(f, at + ".position", l.position, Kind::Number);
            attenuation(f, at, l.attenuation);
          } else if constexpr (std::is_same_v<L, DirectionalLight>) {
            vec(f, at + ".direction", l.direction, Kind::Number);
          } else if constexpr (std::is_same_v<L, SpotLight>) {
            vec(f, at + ".position", l.position, Kind::Number);
            vec(f, at + ".direction", l.direction, Kind::Number);
            f(at + ".cutoff_deg", l.cutoff_deg, Kind::Number);
            attenuation(f, at, l.attenuation);
          }
          vec(f, at + ".color", l.color, Kind::Number);
        },
        s.lights[k]);
  }
}

double maxChannel(const glm::dvec3& c) { return std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)}); }

// One factor of the bound, with the field it comes from.
struct Factor {
  double value = 1.0;
  std::string field;  // empty: the factor is 1 by definition
};

struct Bound {
  Factor C, K, F, L, M;
  double value() const { return 4.0 * C.value * K.value * F.value * std::max(1.0, L.value) * M.value; }
};

// M, the luma-only mode's factor (colour/luma_only.h): the model runs on
// grey inputs no larger than the colours (a luma is a convex combination
// of the channels), so its lit grey is within the bound; then yiq forms
// C + (Y_out - Y_C): at most 2 x that; cie_lstar forms
// f^-1(f(t) + f(Y_out) - f(Y_C)), at most (2 cbrt(B))^3 = 8 B, and the XYZ->RGB
// rows' |entries| times the white point sum to < 8: 64 x.
constexpr double kLumaOnlyFactor[2] = {2.0, 64.0};

// The bound for one material (named `prefix` in messages).
Bound shadingFactors(const Scene& s, const Material& mat, const std::string& prefix) {
  Bound b;
  if (mat.texture) {
    if (mat.texture->source == TextureSpec::Source::Image)
      b.C = {kMaxTexelValue, prefix + ".texture.path"};
    else if (mat.texture->source == TextureSpec::Source::Model)
      b.C = maxChannel(mat.base_color) > kMaxTexelValue ? Factor{maxChannel(mat.base_color), prefix + ".base_color"}
                                                          : Factor{kMaxTexelValue, prefix + ".texture.source"};
  } else if (maxChannel(mat.base_color) > 1.0) {
    b.C = {maxChannel(mat.base_color), prefix + ".base_color"};
  }
  const std::string m = prefix + ".model";
  // K: the sum of the |coefficients| (shading/model/params.h Role), named
  // by the largest (the first of equals); F: the sum of the |colours|,
  // named by the one of the largest channel.
  std::visit(
      [&]<class M>(const M& mm) {
        double k_sum = 0.0, k_top = 0.0;
        std::string k_field;
        glm::dvec3 f_sum(0.0);
        double f_top = 0.0;
        const char* f_field = "c0";
        // A Specular number multiplies a term that may exceed 1: by the
        // model's specularGain() where it has one (cook_torrance's
        // microfacet peak, ~1 / alpha^3), else 1 (clamp(R.V)^n <= 1). The
        // term is formed before the number multiplies it, so a number
        // below 1 does not shrink what must fit: the gain counts at least
        // once (ks 1e-30 let alpha 3e-22 through, whose S overflowed float);
        // with ks = 0 the term is not formed (Shader's specular_).
        double gain = 1.0;
        if constexpr (requires { mm.specularGain(); }) gain = mm.specularGain();
        model::forEachParam(mm, model::Overloaded{
                                    [&](const model::NumberParam<M>& p, double v) {
                                      if (p.role == model::Role::None) return;
                                      std::string field = m + "." + p.name;
                                      if (p.role == model::Role::Specular && gain > 1.0 && v != 0.0) {
                                        // Named by the larger of the two: ks, or the
                                        // parameter that sets the gain.
                                        if constexpr (requires { M::kSpecularGainParam; })
                                          if (gain > std::abs(v)) field = m + "." + M::kSpecularGainParam;
                                        v = std::max(std::abs(v), 1.0) * gain;
                                      }
                                      k_sum += std::abs(v);
                                      if (k_field.empty() || std::abs(v) > k_top) k_field = field, k_top = std::abs(v);
                                    },
                                    [&](const model::ColourParam<M>& p, const glm::dvec3& c) {
                                      f_sum += glm::abs(c);
                                      if (maxChannel(c) > f_top) f_field = p.name, f_top = maxChannel(c);
                                    },
                                    [](const auto&, const auto&) {}});  // a choice: no number
        if (k_sum > 1.0) b.K = {k_sum, k_field};
        if (maxChannel(f_sum) > 1.0) b.F = {maxChannel(f_sum), m + "." + f_field};
      },
      mat.model);
  if (mat.luma_only) b.M = {kLumaOnlyFactor[size_t(*mat.luma_only)], prefix + ".luma_only"};
  double top = -1.0;
  b.L.value = 0.0;
  for (size_t k = 0; k < s.lights.size(); ++k) {
    const std::string at = "lights[" + std::to_string(k) + "]";
    std::visit(
        [&](const auto& l) {
          using Lt = std::decay_t<decltype(l)>;
          double term = maxChannel(l.color);
          std::string field = at + ".color";
          if constexpr (std::is_same_v<Lt, PointLight> || std::is_same_v<Lt, SpotLight>) {
            if (!l.attenuation.isNone()) {
              const double att = 1.0 / l.attenuation.constant;
              if (att > term) field = at + ".attenuation.constant";
              term *= att;
            }
          }
          b.L.value += term;
          if (term > top) top = term, b.L.field = field;
        },
        s.lights[k]);
  }
  return b;
}

// Every material the scene shades with: the default, then each object's own.
std::vector<std::pair<const Material*, std::string>> materials(const Scene& s) {
  std::vector<std::pair<const Material*, std::string>> out{{&s.material, "material"}};
  for (size_t k = 0; k < s.objects.size(); ++k)
    if (s.objects[k].material) out.push_back({&*s.objects[k].material, "objects[" + std::to_string(k) + "].material"});
  return out;
}

// The largest of the materials' bounds.
Bound shadingFactors(const Scene& s) {
  Bound worst;
  bool first = true;
  for (const auto& [mat, prefix] : materials(s)) {
    Bound b = shadingFactors(s, *mat, prefix);
    if (first || b.value() > worst.value()) worst = b, first = false;
  }
  return worst;
}

// The specular coefficient (Role::Specular), 0 for a model without one.
double ksOf(const Material& m) {
  double ks = 0.0;
  std::visit(
      [&]<class M>(const M& mm) {
        model::forEachParam(mm, model::Overloaded{[&](const model::NumberParam<M>& p, double v) {
                                                    if (p.role == model::Role::Specular) ks = v;
                                                  },
                                                  [](const auto&, const auto&) {}});
      },
      m.model);
  return ks;
}

// The field of the largest ks ("objects[1].material.model.ks").
std::string largestKsField(const Scene& s) {
  std::string field = "material.model.ks";
  double ks = -1.0;
  for (const auto& [mat, prefix] : materials(s))
    if (ksOf(*mat) > ks) ks = ksOf(*mat), field = prefix + ".model.ks";
  return field;
}

}  // namespace

PrecisionLimits precisionLimits(Precision p) {
  if (p == Precision::Float) return {1e12, 1e30, 1e-30, 4096.0, 1e36, 512.0};
  return {1e18, 1e300, 1e-300, 1e300, 1e306, 0x1p38};
}

double shadingBound(const Scene& scene) { return shadingFactors(scene).value(); }

// The largest ks over the materials, times the lights' sum.
double specularWeight(const Scene& scene) {
  double ks = 0.0;
  for (const auto& [mat, prefix] : materials(scene)) ks = std::max(ks, ksOf(*mat));
  return ks * shadingFactors(scene).L.value;
}

void checkPrecision(const Scene& scene, Precision p) {
  const PrecisionLimits lim = precisionLimits(p);
  const std::string file = scene.source_file.string();
  const std::string prec = std::string(toString(p)) + " precision";
  const std::string fix = p == Precision::Float
                              ? "; render in double precision (--precision double) or change the value"
                              : "; change the value";
  forEachNumber(scene, [&](const std::string& path, double v, Kind kind) {
    const double max = kind == Kind::Coordinate ? lim.max_coordinate
                       : kind == Kind::UvRepeat ? lim.max_uv_repeat
                                                : lim.max_number;
    const char* what = kind == Kind::Coordinate ? "a coordinate or length of the camera or an object"
                       : kind == Kind::UvRepeat ? "a uv repeat (beyond it the texture coordinates round "
                                                  "by more than an eighth of a texel)"
                                                : "this number";
    if (!(std::abs(v) <= max))
      throw SceneError(file + ": " + path + ": " + num(v) + " is beyond what " + prec + " computes with: " +
                       what + " must be at most " + num(max) + " in magnitude" + fix);
    if (v != 0.0 && !(std::abs(v) >= lim.min_nonzero))
      throw SceneError(file + ": " + path + ": " + num(v) + " is too small for " + prec +
                       " (it would round to 0 or lose its digits): a non-zero number must be at least " +
                       num(lim.min_nonzero) + " in magnitude" + fix + " (0 is allowed)");
  });
  const Bound b = shadingFactors(scene);
  const double B = b.value();
  if (!(B <= lim.max_shading)) {
    // The field of the largest factor leads the message.
    const Factor* lead = &b.L;
    for (const Factor* f : {&b.C, &b.K, &b.F})
      if (f->value > lead->value && !f->field.empty()) lead = f;
    auto part = [](const char* what, const Factor& f) {
      return std::string(what) + " " + num(f.value) + (f.field.empty() ? "" : " (" + f.field + ")");
    };
    throw SceneError(file + ": " + (lead->field.empty() ? "lights" : lead->field) +
                     ": the shading could reach " + num(B) + " = 4 x " + part("surface colour", b.C) + " x " +
                     part("model coefficients", b.K) + " x " + part("Forsyth colours", b.F) + " x " +
                     part("light (colour / attenuation constant, summed)", b.L) + " x " +
                     part("luma-only mode", b.M) + ", beyond " +
                     num(lim.max_shading) + ", the limit of " + prec + fix);
  }
  const double W = specularWeight(scene);
  const double ks = b.L.value > 0.0 ? W / b.L.value : 0.0;
  if (!(W <= lim.max_specular_weight))
    throw SceneError(file + ": " + (ks >= b.L.value || b.L.field.empty() ? largestKsField(scene) : b.L.field) +
                     ": ks x light (colour / attenuation constant, summed) = " + num(ks) + " x " +
                     num(b.L.value) + " = " + num(W) + " is beyond " + num(lim.max_specular_weight) + ", the most " + prec +
                     " shades accurately: the specular power is taken as 0 where it is below " +
                     (p == Precision::Float ? "2^-25" : "2^-54") +
                     " (models::phongSpecular), an error of up to that times ks x light" + fix);
}

}  // namespace xval
