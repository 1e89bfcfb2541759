#include "povray/pov_native.h"

#include "common/export_common.h"
#include "povray/sdl.h"
#include "shading/model/registry.h"

namespace xval::pov {

namespace {

const char* kNoBuiltIn = " POV-Ray 3.7's finish has diffuse (kd |N.L|^brilliance), phong (R.V) and specular (N.H) "
                         "terms only (use the povray renderer, which computes the model in pigments)";

// A highlight exponent n must be > 0: xval's clamp(.)^0 is 1 everywhere
// (pow(0, 0) = 1), POV-Ray's phong and specular are 0 where the cosine is
// <= 0, and `roughness 1/n` has no value at n = 0.
void requireExponent(const char* model, double ks, double n) {
  if (ks != 0.0 && !(n > 0.0))
    throw ExportError(std::string(model) + ": shininess " + num(n) + " with ks " + num(ks) +
                      " is not expressible natively: at n = 0 xval's highlight is 1 everywhere, POV-Ray's is 0 where "
                      "its cosine is <= 0 (and blinn_phong's `roughness 1/n` has no value)");
}

}  // namespace

NativeFinish nativeFinish(const Material& material) {
  NativeFinish f;
  std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, ClassicPhong>) {
          if (m.variant == ClassicPhong::Variant::Course)
            throw ExportError("classic_phong variant course is not expressible natively: its highlight is tinted by "
                              "the surface colour (C (x) Lc ks S) and it has a per-light ambient ka Lc; POV-Ray's "
                              "phong is white and its ambient is the global ambient_light (metallic tints by a "
                              "Fresnel-like function of N.L, not by C)");
          requireExponent("classic_phong", m.ks, m.shininess);
          f.ambient = m.ka, f.diffuse = m.kd, f.phong = m.ks, f.phong_size = m.ks != 0.0 ? m.shininess : 0.0;
        } else if constexpr (std::is_same_v<M, BlinnPhong>) {
          requireExponent("blinn_phong", m.ks, m.shininess);
          // POV-Ray's exponent is 1/roughness (the parser stores the inverse).
          f.ambient = m.ka, f.diffuse = m.kd, f.specular = m.ks, f.roughness = m.ks != 0.0 ? 1.0 / m.shininess : 0.0;
        } else if constexpr (std::is_same_v<M, Lambert>) {
          if (!(m.c0.x == m.c0.y && m.c0.y == m.c0.z))
            throw ExportError("lambert with c0 " + vec(m.c0) +
                              " (not grey) is not expressible natively: POV-Ray's diffuse is one number, and a "
                              "coloured c0 folded into the pigment would colour the ambient term too");
          f.ambient = 1.0, f.diffuse = m.c0.x;
        } else if constexpr (std::is_same_v<M, Minnaert>) {
          // The nearest built-in (pov_native.h): kd (N.L)^k, without (N.V)^(k-1).
          f.ambient = 1.0, f.diffuse = m.kd, f.brilliance = m.k;
        } else {
          throw ExportError(std::string(M::kName) + " has no built-in POV-Ray finish:" + kNoBuiltIn);
        }
      },
      material.model);
  return f;
}

std::string nativeFinishSdl(const NativeFinish& f) {
  std::string s = "finish { ambient " + num(f.ambient) + " diffuse " + num(f.diffuse) + " brilliance " +
                  num(f.brilliance) + " emission 0";
  if (f.phong != 0.0) s += " phong " + num(f.phong) + " phong_size " + num(f.phong_size);
  if (f.specular != 0.0) s += " specular " + num(f.specular) + " roughness " + num(f.roughness);
  return s + " }";
}

NativeLights nativeLights(const Scene& scene) {
  NativeLights out;
  for (size_t k = 0; k < scene.lights.size(); ++k) {
    const Light& l = scene.lights[k];
    if (const auto* a = std::get_if<AmbientLight>(&l)) {
      out.ambient_light += a->color;
      continue;
    }
    const glm::dvec3 colour = std::visit(
        [](const auto& x) -> glm::dvec3 {
          if constexpr (requires { x.color; }) return x.color;
          return glm::dvec3(0.0);
        },
        l);
    const auto sources = lightSourcesOf(l, colour);
    if (!sources) {
      const Attenuation& att =
          std::holds_alternative<PointLight>(l) ? std::get<PointLight>(l).attenuation : std::get<SpotLight>(l).attenuation;
      throw ExportError("lights[" + std::to_string(k) + "].attenuation 1/(" + num(att.constant) + " + " +
                        num(att.linear) + " d + " + num(att.quadratic) +
                        " d^2) is not expressible natively: POV-Ray's lights attenuate only by fade "
                        "(2/(1 + (d/fade_distance)^fade_power)), and no sum of such light sources gives a linear "
                        "and a quadratic term whose roots are complex or nearly equal");
    }
    out.sources.insert(out.sources.end(), sources->begin(), sources->end());
  }
  return out;
}

void checkNativeScene(const Scene& scene) {
  if (scene.shading == ShadingMode::Gouraud)
    throw ExportError("shading \"gouraud\" is not expressible natively: POV-Ray shades every ray hit with its "
                      "finish, it has no per-vertex lighting interpolated across a triangle");
  const MaterialSlots slots = materialSlots(scene);
  for (size_t k = 0; k < slots.materials.size(); ++k) {
    if (!slots.used[k]) continue;
    const Material& m = *slots.materials[k];
    const std::string where = k == 0 ? "material" : "objects[" + std::to_string(k - 1) + "].material";
    if (m.luma_only)
      throw ExportError(where + ".luma_only is not expressible natively: POV-Ray's finish lights the colour, it has "
                        "no luma-only mode");
    try {
      nativeFinish(m);
    } catch (const ExportError& e) {
      throw ExportError(where + ".model: " + e.what());
    }
  }
  nativeLights(scene);
}

}  // namespace xval::pov
