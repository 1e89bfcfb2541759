#include "blender/native_bsdf.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "shading/models.h"

namespace xval {

namespace {

constexpr double kPi = std::numbers::pi;
// Ours = 4 pi^2 x Cycles' pass for a RAW-imported point light (the header).
constexpr double kPassToOurs = 4.0 * kPi * kPi;
// Cycles' Oren-Nayar normalisation: a = 1 / (pi + kOrenNayarCyclesK sigma)
// (bsdf_oren_nayar.h); models::orenNayarCyclesAB holds ours (pi times it).
constexpr double kOrenNayarCyclesK = (3.0 * kPi - 4.0) / 6.0;
// Cycles returns no highlight for alpha_x alpha_y <= 1e-7
// (bsdf_microfacet.h), i.e. alpha <= sqrt(1e-7); and turns an unlinked
// Glossy Roughness <= 1e-4 into a sharp reflection (shader_nodes.cpp).
constexpr double kSmallestGlossyAlpha = 3.1623e-4;  // > sqrt(1e-7) = 3.16228e-4

[[noreturn]] void refuse(const Scene& s, const std::string& why) {
  throw std::runtime_error(s.name + ": the native tier (Blender's own BSDFs) " + why);
}

void checkSetting(const Scene& s) {
  if (s.material.texture || s.material.base_color != glm::dvec3(1.0))
    refuse(s, "needs an untextured white material (base_color [1,1,1], no texture): Blender's pass is "
              "compared without its colour");
  if (s.material.luma_only) refuse(s, "has no luma-only mode: Blender's BSDFs light the colour");
  if (hasObjectMaterials(s)) refuse(s, "needs the scene's one material on every object");
  if (s.lights.size() != 1 || !std::holds_alternative<PointLight>(s.lights[0]))
    refuse(s, "needs exactly one light, a point light (no ambient, no second light): found " +
                  std::to_string(s.lights.size()) + " light(s)");
  const auto& p = std::get<PointLight>(s.lights[0]);
  if (p.color.x != p.color.y || p.color.y != p.color.z)
    refuse(s, "needs a white light (I, I, I): Blender's pass is compared without its colour");
  if (p.attenuation.linear != 0.0 || p.attenuation.quadratic != 1.0 || p.attenuation.constant > 1e-6)
    refuse(s, "needs the light's attenuation {constant ~ 0 (<= 1e-6), linear 0, quadratic 1}: Cycles' "
              "point light falls off as the inverse square");
  if (s.shading != ShadingMode::Phong || !s.normalize_normal)
    refuse(s, "needs smooth (phong) shading with normalised normals, as Cycles shades");
}

}  // namespace

double cyclesRoughnessForQualitative(double sigma) {
  const models::OrenNayarAB q = models::orenNayarQualitativeAB(sigma);
  return q.b / q.a;
}

double cyclesGlossyRoughness(double alpha) { return std::sqrt(alpha); }

const char* glossyName(NativeBsdf::Glossy g) {
  switch (g) {
    case NativeBsdf::Glossy::Ggx: return "ggx";
    case NativeBsdf::Glossy::Beckmann: return "beckmann";
    case NativeBsdf::Glossy::None: break;
  }
  return "none";
}

NativeBsdf nativeBsdf(const Scene& s) {
  checkSetting(s);
  NativeBsdf n;
  const LightingModel& m = s.material.model;
  if (const auto* l = std::get_if<Lambert>(&m)) {
    if (l->c0 != glm::dvec3(1.0)) refuse(s, "needs lambert c0 = [1,1,1]");
    n.diffuse_weight = kPassToOurs;
  } else if (const auto* o = std::get_if<OrenNayar>(&m)) {
    if (o->variant == OrenNayar::Variant::Cycles) {
      // Cycles clamps its Roughness to [0, 1] (bsdf_oren_nayar_setup).
      if (o->sigma > 1.0)
        refuse(s, "cannot render oren_nayar cycles with sigma " + std::to_string(o->sigma) +
                      " > 1: Cycles clamps the Diffuse BSDF's Roughness to [0, 1]");
      n.diffuse_roughness = o->sigma;
      n.diffuse_weight = kPassToOurs * o->kd;
    } else {
      // Where s > 0: ours = kd A x (1 + (B/A) t) N.L; Cycles' eval with
      // Roughness r = B/A is (1 + r t) N.L / (pi + K r), so
      // ours = kd A (pi + K r) eval x I / d^2 = 4 pi kd A (pi + K r) DiffDir.
      const models::OrenNayarAB q = models::orenNayarQualitativeAB(o->sigma);
      n.diffuse_roughness = cyclesRoughnessForQualitative(o->sigma);
      n.diffuse_weight = 4.0 * kPi * o->kd * q.a * (kPi + kOrenNayarCyclesK * n.diffuse_roughness);
    }
  } else if (const auto* c = std::get_if<CookTorrance>(&m)) {
    if (c->geometry != models::MicrofacetG::Smith || c->fresnel != models::MicrofacetF::None)
      refuse(s, "renders cook_torrance only as Cycles' Glossy BSDF: geometry smith, fresnel none (the "
                "scene has geometry " + std::string(c->geometry == models::MicrofacetG::Smith ? "smith" : "cook_torrance") +
                ", fresnel " + (c->fresnel == models::MicrofacetF::None ? "none" : "schlick") + ")");
    if (c->roughness < kSmallestGlossyAlpha)
      refuse(s, "cannot render cook_torrance roughness (alpha) " + std::to_string(c->roughness) +
                    " below 3.1623e-4: Cycles' Glossy BSDF returns no highlight for alpha^2 <= 1e-7");
    n.diffuse_weight = kPassToOurs * c->kd;
    if (c->ks > 0.0) {
      n.glossy = c->distribution == models::MicrofacetD::Ggx ? NativeBsdf::Glossy::Ggx : NativeBsdf::Glossy::Beckmann;
      n.glossy_roughness = cyclesGlossyRoughness(c->roughness);
      n.glossy_weight = kPassToOurs * c->ks;
    }
  } else {
    refuse(s, "renders lambert, oren_nayar and cook_torrance (smith, no Fresnel) only: Blender has no "
              "built-in BSDF for the scene's model");
  }
  return n;
}

NativeColours eeveeColours(const NativeBsdf& n) {
  NativeColours c;
  c.scale = std::max(n.diffuse_weight, n.glossy_weight);
  if (!(c.scale > 0.0)) return {0.0, 0.0, 1.0};  // kd = ks = 0: black either way
  c.diffuse = n.diffuse_weight / c.scale;
  c.glossy = n.glossy_weight / c.scale;
  return c;
}

Image scaleNativeCombined(double scale, const Image& combined) {
  Image out = combined;
  out.raw.clear();
  const float k = float(scale);
  for (size_t i = 0; i < out.rgba.size(); i += 4)
    for (size_t c = 0; c < 3; ++c) out.rgba[i + c] = std::clamp(k * combined.rgba[i + c], 0.0f, 1.0f);
  return out;
}

Image combineNativePasses(const NativeBsdf& n, const Image& diffdir, const Image& glossdir) {
  if (diffdir.width != glossdir.width || diffdir.height != glossdir.height)
    throw std::invalid_argument("combineNativePasses: DiffDir and GlossDir differ in size");
  Image out = diffdir;
  out.raw.clear();
  const float wd = float(n.diffuse_weight), wg = float(n.glossy_weight);
  for (size_t i = 0; i < out.rgba.size(); i += 4)
    for (size_t c = 0; c < 3; ++c)
      out.rgba[i + c] = std::clamp(wd * diffdir.rgba[i + c] + wg * glossdir.rgba[i + c], 0.0f, 1.0f);
  return out;
}

}  // namespace xval
