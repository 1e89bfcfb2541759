#include "scene_file/scene_writer.h"
#include "image/metric_criteria.h"

namespace xval {

using J = nlohmann::ordered_json;

namespace {
J v3(glm::dvec3 v) { return J::array({v.x, v.y, v.z}); }
J v2(glm::dvec2 v) { return J::array({v.x, v.y}); }

J attenuation(const Attenuation& a) {
  return {{"constant", a.constant}, {"linear", a.linear}, {"quadratic", a.quadratic}};
}

J shape(const Shape& s) {
  if (auto* k = std::get_if<TorusKnot>(&s))
    return {{"shape", "torus_knot"},        {"p", k->p},
            {"q", k->q},                    {"major_radius", k->major_radius},
            {"minor_radius", k->minor_radius}, {"tube_radius", k->tube_radius},
            {"segments_along", k->segments_along}, {"segments_around", k->segments_around},
            {"uv_repeat", v2(k->uv_repeat)}, {"center", v3(k->center)}};
  if (auto* p = std::get_if<UvSphere>(&s))
    return {{"shape", "sphere"},
            {"center", v3(p->center)},
            {"radius", p->radius},
            {"segments_longitude", p->segments_longitude},
            {"segments_latitude", p->segments_latitude},
            {"uv_repeat", v2(p->uv_repeat)}};
  if (auto* m = std::get_if<MeshFile>(&s)) return {{"shape", "mesh"}, {"path", m->path.string()}};
  const auto& p = std::get<Plane>(s);
  return {{"shape", "plane"},
          {"center", v3(p.center)},
          {"normal", v3(p.normal)},
          {"size", v2(p.size)},
          {"uv_repeat", v2(p.uv_repeat)}};
}

// The model's type and its parameters, in the loader's order
// (shading/model/params.h).
J model(const LightingModel& m) {
  J j = {{"type", modelName(m)}};
  std::visit(
      [&]<class M>(const M& mm) {
        model::forEachParam(mm, model::Overloaded{
                                    [&](const model::NumberParam<M>& p, double v) { j[p.name] = v; },
                                    [&](const model::ColourParam<M>& p, const dvec3& v) { j[p.name] = v3(v); },
                                    [&]<class E, size_t N>(const model::ChoiceParam<M, E, N>& p, E v) {
                                      j[p.name] = p.nameOf(v);
                                    }});
      },
      m);
  return j;
}

J material(const Material& m, const std::string* texture_path) {
  J mat = {{"model", model(m.model)}};
  if (m.texture) {
    const TextureSpec& t = *m.texture;
    J tex = {{"source", t.source == TextureSpec::Source::Brick   ? "brick"
                        : t.source == TextureSpec::Source::Model ? "model"
                                                                 : "image"}};
    if (t.source == TextureSpec::Source::Image) tex["path"] = texture_path ? *texture_path : t.path.string();
    tex["filter"] = toString(t.filter);
    mat["texture"] = tex;
  }
  if (!m.texture || m.texture->source == TextureSpec::Source::Model) mat["base_color"] = v3(m.base_color);
  if (m.luma_only) mat["luma_only"] = toString(*m.luma_only);
  return mat;
}

J object(const SceneObject& o) {
  J j = shape(o.shape);
  if (!o.transform.isIdentity()) {
    const ObjectTransform& t = o.transform;
    j["transform"] = {{"scale", v3(t.scale)},
                      {"rotate", {{"axis", v3(t.rotate.axis)}, {"angle_deg", t.rotate.angle_deg}}},
                      {"translate", v3(t.translate)}};
  }
  if (o.material) j["material"] = material(*o.material, nullptr);
  return j;
}

J light(const Light& l) {
  if (auto* p = std::get_if<PointLight>(&l))
    return {{"type", "point"}, {"position", v3(p->position)}, {"color", v3(p->color)},
            {"attenuation", attenuation(p->attenuation)}};
  if (auto* d = std::get_if<DirectionalLight>(&l))
    return {{"type", "directional"}, {"direction", v3(d->direction)}, {"color", v3(d->color)}};
  if (auto* s = std::get_if<SpotLight>(&l))
    return {{"type", "spot"},          {"position", v3(s->position)},
            {"direction", v3(s->direction)}, {"cutoff_deg", s->cutoff_deg},
            {"color", v3(s->color)},   {"attenuation", attenuation(s->attenuation)}};
  return {{"type", "ambient"}, {"color", v3(std::get<AmbientLight>(l).color)}};
}
}  // namespace

J sceneToJson(const Scene& s, const std::string* texture_path) {
  J j;
  j["format"] = "xval-scene/1";
  j["name"] = s.name;
  const Camera& c = s.camera;
  j["camera"] = {{"position", v3(c.position)}, {"target", v3(c.target)}, {"up", v3(c.up)},
                 {"fov_y_deg", c.fov_y_deg},   {"width", c.width},      {"height", c.height}};
  j["objects"] = J::array();
  for (const auto& o : s.objects) j["objects"].push_back(object(o));
  j["material"] = material(s.material, texture_path);
  j["lights"] = J::array();
  for (const auto& l : s.lights) j["lights"].push_back(light(l));
  j["shading"] = toString(s.shading);
  if (!s.normalize_normal) j["normalize_normal"] = false;
  j["render"] = {{"spp", s.render.spp}, {"precision", toString(s.render.precision)}};
  if (!s.tolerances.empty()) {
    J t;
    for (const auto& d : s.tolerances) {
      J e;
      if (d.max_abs_16bit) e["max_abs_16bit"] = *d.max_abs_16bit;
      if (d.fraction) e["fraction"] = *d.fraction;
      if (d.max_unexplained_16bit) e["max_unexplained_16bit"] = *d.max_unexplained_16bit;
      if (d.exclude_backfacing) e["exclude_backfacing"] = true;
      if (!d.metrics.empty()) e["metrics"] = metricCriteriaJson(d.metrics);
      e["reason"] = d.reason;
      t[d.renderer] = e;
    }
    j["tolerances"] = t;
  }
  if (!s.renderers.empty()) j["renderers"] = s.renderers;
  for (const auto& [id, why] : s.findings) j["findings"][id] = why;
  return j;
}

}  // namespace xval
