#include "gltf/shading_constants.h"

#include <glm/glm.hpp>

#include "camera/camera.h"
#include "shading/models.h"
#include "shading/shader.h"

namespace xval {

namespace {

using nlohmann::ordered_json;

ordered_json vec(glm::dvec3 v) { return ordered_json::array({v.x, v.y, v.z}); }

ordered_json lightConstants(const PreparedLight<double>& l) {
  using K = PreparedLight<double>::Kind;
  ordered_json j;
  j["kind"] = l.kind == K::Point ? "point" : l.kind == K::Spot ? "spot" : "directional";
  j["colour"] = vec(l.color);
  j["luma"] = l.color_luma;
  if (l.kind == K::Directional) {
    j["to_light"] = vec(-l.direction);
  } else {
    j["position"] = vec(l.position);
    j["attenuated"] = l.has_attenuation;
    j["attenuation"] = ordered_json::array({l.att_c, l.att_l, l.att_q});
  }
  if (l.kind == K::Spot) {
    j["minus_axis"] = vec(-l.direction);
    j["cos_cutoff"] = l.cos_cutoff;
  }
  return j;
}

struct ModelConstants {
  const Shader<double>& shader;
  ordered_json& j;
  void operator()(const ClassicPhong& m) const {
    j["course"] = m.variant == ClassicPhong::Variant::Course;
    j["ka"] = m.ka, j["kd"] = m.kd, j["ks"] = m.ks, j["shininess"] = m.shininess;
    j["specular"] = shader.usesSpecular();
    j["ka_ambient"] = vec(m.ka * shader.ambient());
  }
  void operator()(const YiqLuma& m) const {
    j["kd"] = m.kd, j["ks"] = m.ks, j["shininess"] = m.shininess;
    j["luma_offset"] = m.luma_offset;
    j["specular"] = shader.usesSpecular();
    j["ambient_luma"] = shader.ambientLuma();
    j["luma_row"] = ordered_json::array(
        {models::kRgbToYiq[0][0], models::kRgbToYiq[0][1], models::kRgbToYiq[0][2]});
  }
  void ambient() const { j["ambient"] = vec(shader.ambient()); }
  void operator()(const Lambert& m) const {
    ambient();
    j["c0"] = vec(m.c0);
  }
  void operator()(const WrapAround& m) const {
    ambient();
    j["c0"] = vec(m.c0), j["factor"] = m.factor, j["wrap_divisor"] = 1.0 + m.factor;
  }
  void operator()(const Hemispherical& m) const {
    ambient();
    j["c0"] = vec(m.c0), j["c2"] = vec(m.c2), j["c0_minus_c2"] = vec(m.c0 - m.c2);
  }
  void operator()(const BiDirectional& m) const {
    ambient();
    j["c0"] = vec(m.c0), j["c2"] = vec(m.c2);
  }
  void operator()(const Trilight& m) const {
    ambient();
    j["c0"] = vec(m.c0), j["c1"] = vec(m.c1), j["c2"] = vec(m.c2);
  }
  // minnaert, blinn_phong, oren_nayar
  void operator()(const Minnaert& m) const {
    ambient();
    j["kd"] = m.kd, j["k"] = m.k;
  }
  void operator()(const BlinnPhong& m) const {
    j["ka"] = m.ka, j["kd"] = m.kd, j["ks"] = m.ks, j["shininess"] = m.shininess;
    j["specular"] = shader.usesSpecular();
    j["ka_ambient"] = vec(m.ka * shader.ambient());
  }
  void operator()(const OrenNayar& m) const {
    ambient();
    const bool cycles = m.variant == OrenNayar::Variant::Cycles;
    const models::OrenNayarAB ab = cycles ? models::orenNayarCyclesAB(m.sigma) : models::orenNayarQualitativeAB(m.sigma);
    j["kd"] = m.kd, j["sigma"] = m.sigma, j["cycles"] = cycles, j["a"] = ab.a, j["b"] = ab.b;
  }
  void operator()(const CookTorrance& m) const {
    ambient();
    const auto p = CookTorrance::params();
    j["kd"] = m.kd, j["ks"] = m.ks, j["specular"] = shader.usesSpecular();
    j["distribution"] = std::get<0>(p).nameOf(m.distribution);
    j["geometry"] = std::get<1>(p).nameOf(m.geometry);
    j["fresnel"] = std::get<2>(p).nameOf(m.fresnel);
    j["f0"] = m.f0, j["roughness"] = m.roughness;  // alpha
    j["vgroove_min_vh"] = models::kVGrooveMinVh<double>;
  }
};

// The luma-only mode's constants (colour/luma_only.h; colour/cie.h,
// colour/yiq.h): the rows of Y_C (surface_row) and of Y(G) (light_row);
// for cie_lstar also relative XYZ's rows, their inverse's, and f's knee,
// slope, offset 4/29 and its inverse's knee 6/29. The lights and ambients
// above are then already the greys (the Shader prepares greyLights).
ordered_json lumaOnlyConstants(LumaSpace s) {
  ordered_json j;
  auto row = [](auto f) { return ordered_json::array({f(0), f(1), f(2)}); };
  if (s == LumaSpace::Yiq) {
    const double white = colour::kRgbToYiq[0][0] + colour::kRgbToYiq[0][1] + colour::kRgbToYiq[0][2];
    j["surface_row"] = row([](int k) { return colour::kRgbToYiq[0][k]; });
    j["light_row"] = row([&](int k) { return colour::kRgbToYiq[0][k] / white; });
    return j;
  }
  ordered_json to = ordered_json::array(), from = ordered_json::array();
  for (int r = 0; r < 3; ++r) {
    to.push_back(row([r](int k) { return colour::kRgbToXyz[r][k] / colour::kWhiteXyz[r]; }));
    from.push_back(row([r](int k) { return colour::kXyzToRgb.m[r][k] * colour::kWhiteXyz[k]; }));
  }
  j["surface_row"] = to[1];
  j["light_row"] = to[1];
  j["to_relative_xyz"] = to;
  j["from_relative_xyz"] = from;
  j["knee"] = colour::kLabKnee, j["slope"] = colour::kLabSlope, j["offset"] = 4.0 / 29.0;
  j["inverse_knee"] = colour::kLabDelta;
  return j;
}

}  // namespace

ordered_json shadingConstants(const Scene& scene) { return shadingConstants(scene, scene.material); }

ordered_json shadingConstants(const Scene& scene, const Material& material) {
  const Shader<double> shader(material, scene.lights);
  ordered_json j;
  j["shading"] = toString(scene.shading);
  j["normalize_normal"] = scene.normalize_normal;
  j["blender_to_world"] = ordered_json::array({ordered_json::array({1.0, 0.0, 0.0}),
                                               ordered_json::array({0.0, 0.0, 1.0}),
                                               ordered_json::array({0.0, -1.0, 0.0})});
  j["eye"] = vec(CameraRays(scene.camera).origin);
  j["base_colour"] = vec(material.base_color);
  if (material.texture)
    j["texture_filter"] = toString(material.texture->filter);
  else
    j["texture_filter"] = nullptr;
  j["model"] = modelName(material.model);
  std::visit(ModelConstants{shader, j}, material.model);
  if (material.luma_only) {
    j["luma_only"] = toString(*material.luma_only);
    j["luma_only_constants"] = lumaOnlyConstants(*material.luma_only);
  }
  ordered_json lights = ordered_json::array();
  for (const auto& l : shader.lights()) lights.push_back(lightConstants(l));
  j["lights"] = lights;
  return j;
}

}  // namespace xval
