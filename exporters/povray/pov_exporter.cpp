#include "povray/pov_exporter.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <fstream>
#include <optional>
#include <sstream>

#include "camera/camera.h"
#include "files/atomic_write.h"
#include "geometry/mesh.h"
#include "image/image.h"
#include "povray/pigment_tree.h"
#include "povray/sdl.h"
#include "shading/models.h"
#include "shading/shader.h"
#include "shading/surface_colour.h"
#include "texture/texture.h"

namespace xval {

using namespace pov;
using glm::dvec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

// (1 + N.L) / 2 for a light, exactly (docs/povray-export.md).
std::string slopePattern(const Light& l) {
  std::string base;
  if (auto* d = std::get_if<DirectionalLight>(&l))
    base = "slope { " + vec(-glm::normalize(d->direction)) + " }";
  else if (auto* p = std::get_if<PointLight>(&l)) base = "slope { point_at " + vec(p->position) + " }";
  else base = "slope { point_at " + vec(std::get<SpotLight>(l).position) + " }";
  return base + " sine_wave frequency -0.5 phase 0.75";
}

std::string distanceExpr(dvec3 p) {
  return "sqrt((x - " + num(p.x) + ")*(x - " + num(p.x) + ") + (y - " + num(p.y) + ")*(y - " +
         num(p.y) + ") + (z - " + num(p.z) + ")*(z - " + num(p.z) + "))";
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
std::string attPattern(const LightInfo& l) {
  std::string d = distanceExpr(l.position);
  return "function { " + num(l.att.constant) + " / (" + num(l.att.constant) + " + " +
         num(l.att.linear) + " * " + d + " + " + num(l.att.quadratic) + " * " + d + " * " + d +
         ") }";
}

// 1 inside the spot's cone (dot(p - p_light, axis) >= cos(cutoff) d), else 0.
std::string conePattern(const LightInfo& l) {
  dvec3 p = l.position, a = l.axis;
  double c = std::cos(l.cutoff_deg * kPi / 180.0);
  return "function { select((x - " + num(p.x) + ") * " + num(a.x) + " + (y - " + num(p.y) +
         ") * " + num(a.y) + " + (z - " + num(p.z) + ") * " + num(a.z) + " - " + num(c) + " * " +
         distanceExpr(p) + ", 0, 1, 1) }";
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
std::vector<std::pair<double, dvec3>> diffuseBreakpoints(const LightingModel& model) {
  using P = std::vector<std::pair<double, dvec3>>;
  if (auto* m = std::get_if<ClassicPhong>(&model)) return P{{-1, dvec3(0)}, {0, dvec3(0)}, {1, dvec3(m->kd)}};
  if (auto* m = std::get_if<Lambert>(&model)) return P{{-1, dvec3(0)}, {0, dvec3(0)}, {1, m->c0}};
  if (auto* m = std::get_if<WrapAround>(&model))
    return P{{-1, dvec3(0)}, {-m->factor, dvec3(0)}, {1, m->c0}};
  if (auto* m = std::get_if<Hemispherical>(&model)) return P{{-1, m->c2}, {1, m->c0}};
  if (auto* m = std::get_if<BiDirectional>(&model)) return P{{-1, m->c2}, {0, dvec3(0)}, {1, m->c0}};
  if (auto* m = std::get_if<Trilight>(&model)) return P{{-1, m->c2}, {0, m->c1}, {1, m->c0}};
  return {};
}

dvec3 ambientSum(const Scene& s) {
  dvec3 a(0.0);
  for (const auto& l : s.lights)
    if (auto* am = std::get_if<AmbientLight>(&l)) a += am->color;
  return a;
}

// Emission for classic Phong's ambient + diffuse and the Forsyth family:
// C (x) K with K = A' + sum_l [lit] att Lc (x) g(N.L) (+ course's per-light ka).
Pigment emissionLinear(const Scene& s, const std::vector<LightInfo>& lights) {
  const LightingModel& model = s.material.model;
  dvec3 ambient = ambientSum(s);
  const auto* phong = std::get_if<ClassicPhong>(&model);
  std::vector<Pigment> terms;
  terms.push_back(constant(phong ? phong->ka * ambient : ambient));
  auto points = diffuseBreakpoints(model);
  for (const auto& l : lights) {
    auto scaled_points = points;
    for (auto& p : scaled_points) p.second *= l.colour;
    terms.push_back(perLight(l, slopeMap(*l.light, scaled_points), true));
    if (phong && phong->variant == ClassicPhong::Variant::Course && phong->ka != 0.0)
      terms.push_back(perLight(l, constant(phong->ka * l.colour), false));
  }
  Pigment k = sum(std::move(terms));
  // Multiply by the surface colour C at the leaves.
  const bool textured = s.material.texture.has_value();
  const dvec3 base = s.material.base_color;
  return mapLeaves(k, [&](const PigmentNode& leaf) {
    return textured ? affine(glm::dmat3(leaf.b.x, 0, 0, 0, leaf.b.y, 0, 0, 0, leaf.b.z), dvec3(0.0))
                    : constant(base * leaf.b);
  });
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
  if (lights.size() != 1 || lights[0].has_att)
    throw ExportError(
        "yiq_luma: Dl = saturate(A + kd sum_l att Y(Lc) saturate(N.L)) can reach 1 here (A + kd sum "
        "Y(Lc)/c = " + num(a + wsum) + " > 1) and then is not a sum of per-light terms; POV-Ray can "
        "compute it exactly in one render only for a single light without attenuation (or when "
        "the sum cannot reach 1)");
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

struct Specular {
  double ks = 0.0, shininess = 0.0;
  std::vector<std::string> light_sources;
  std::optional<std::string> att_texture_map;  // pattern for the one general attenuation
};

Specular specular(const Scene& s, const std::vector<LightInfo>& lights) {
  Specular sp;
  const LightingModel& model = s.material.model;
  std::function<dvec3(const LightInfo&)> colour;
  if (auto* m = std::get_if<ClassicPhong>(&model)) {
    sp.ks = m->ks, sp.shininess = m->shininess;
    if (m->variant == ClassicPhong::Variant::Course) {
      if (s.material.texture && m->ks != 0.0)
        throw ExportError(
            "classic_phong variant course with a texture and ks > 0: its highlight is the texture "
            "colour times POV-Ray's phong term, a per-channel product POV-Ray cannot form in one "
            "render (its `metallic` tint adds a Fresnel factor)");
      colour = [&s](const LightInfo& l) { return l.colour * s.material.base_color; };
    } else {
      colour = [](const LightInfo& l) { return l.colour; };
    }
  } else if (auto* m = std::get_if<YiqLuma>(&model)) {
    sp.ks = m->ks, sp.shininess = m->shininess;
    colour = [](const LightInfo& l) { return dvec3(models::lightLuma(l.colour)); };
  }
  if (sp.ks == 0.0) return sp;
  int general = 0;
  for (const auto& l : lights) general += l.has_att && l.att.linear != 0.0;
  if (general > 0 && lights.size() > 1)
    throw ExportError(
        "attenuation with a linear term on a light with a specular highlight, among several "
        "lights: POV-Ray's fade can only express 1/(c + q d^2), and the texture_map that applies "
        "a general attenuation to the highlight would scale every light's highlight");
  for (const auto& l : lights) {
    dvec3 c = colour(l);
    std::string extra;
    std::string location;
    if (l.directional) {
      location = vec(-l.axis);
      extra = " parallel point_at <0, 0, 0>";
    } else {
      location = vec(l.position);
      if (l.has_att) {
        c /= l.att.constant;
        if (l.att.linear != 0.0) {
          sp.att_texture_map = attPattern(l);
        } else if (l.att.quadratic != 0.0) {
          // 2/(1 + (d/fd)^2) with fd = sqrt(c/q) is 2c/(c + q d^2).
          c /= 2.0;
          extra = " fade_distance " + num(std::sqrt(l.att.constant / l.att.quadratic)) +
                  " fade_power 2";
        }
      }
      if (l.spot)
        extra += " spotlight point_at " + vec(l.position + l.axis) + " radius " +
                 num(l.cutoff_deg) + " falloff " + num(l.cutoff_deg) + " tightness 0";
    }
    sp.light_sources.push_back("light_source { " + location + " rgb " + vec(c) + extra + " }");
  }
  return sp;
}


std::string finish(double ks, double n) {
  std::string f = "finish { ambient 0 diffuse 0 emission 1";
  if (ks != 0.0) f += " phong " + num(ks) + " phong_size " + num(n);
  return f + " }";
}

// Gouraud in POV-Ray: an image holding, per triangle, a 2x2 texel block
// (c0, c1 / c2, c1 + c2 - c0) and uv at the three texel centres of c0, c1,
// c2. Bilinear interpolation (`interpolate 2`) over such a block is the
// affine function c0 + s (c1 - c0) + t (c2 - c0), and POV-Ray's mesh uv is
// barycentric, so the colour is the exact barycentric interpolation of the
// vertex colours. Measured alternatives: a mesh2 texture_list is up to
// 230/65535 off along triangle edges (POV-Ray weights three textures with
// single-precision smooth-triangle distances); an OpenEXR image_map is read
// as half floats (up to 16/65535 off). So the colours go into two 16-bit
// PNGs, coarse and fine: c = lo + range (hi16 + lo16 / 65535) / 65535 per
// channel, exact to ~1e-9.
struct GouraudImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
  std::vector<glm::dvec2> uvs;  // 3 per triangle, POV-Ray's v (bottom-up)
};

GouraudImage gouraudImage(const TriangleMesh& m, const std::vector<dvec3>& colours) {
  GouraudImage g;
  const size_t n = m.triangles.size();
  const int cols = std::max(1, int(std::ceil(std::sqrt(double(n)))));
  const int rows = int((n + cols - 1) / cols);
  g.width = 2 * cols, g.height = 2 * rows;
  g.rgb.assign(size_t(g.width) * g.height * 3, 0.0f);
  auto put = [&g](int x, int y, dvec3 c) {
    for (int k = 0; k < 3; ++k) g.rgb[(size_t(y) * g.width + x) * 3 + k] = float(c[k]);
  };
  auto centre = [&g](int x, int y) {
    return glm::dvec2((x + 0.5) / g.width, 1.0 - (y + 0.5) / g.height);
  };
  for (size_t t = 0; t < n; ++t) {
    const int x = 2 * int(t % cols), y = 2 * int(t / cols);
    const dvec3 c0 = colours[m.triangles[t][0]], c1 = colours[m.triangles[t][1]],
                c2 = colours[m.triangles[t][2]];
    put(x, y, c0), put(x + 1, y, c1), put(x, y + 1, c2), put(x + 1, y + 1, c1 + c2 - c0);
    g.uvs.push_back(centre(x, y));
    g.uvs.push_back(centre(x + 1, y));
    g.uvs.push_back(centre(x, y + 1));
  }
  return g;
}

// Writes the two PNGs of a GouraudImage and returns SDL declaring the
// pigment `name` that reads them back as the colours.
std::string gouraudPigment(const GouraudImage& g, const std::filesystem::path& dir,
                           const std::string& stem, const std::string& name) {
  dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (size_t i = 0; i < g.rgb.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], double(g.rgb[i]));
    hi[i % 3] = std::max(hi[i % 3], double(g.rgb[i]));
  }
  dvec3 range = hi - lo;
  for (int c = 0; c < 3; ++c)
    if (!(range[c] > 0)) range[c] = 1.0;
  Image coarse(g.width, g.height, false), fine(g.width, g.height, false);
  for (size_t i = 0; i < size_t(g.width) * g.height; ++i) {
    for (int c = 0; c < 3; ++c) {
      double q = std::clamp((double(g.rgb[i * 3 + c]) - lo[c]) / range[c], 0.0, 1.0) * 65535.0;
      double a = std::min(std::floor(q), 65535.0);
      double b = std::round((q - a) * 65535.0);
      coarse.rgba[i * 4 + c] = float(a / 65535.0);
      fine.rgba[i * 4 + c] = float(b / 65535.0);
    }
    coarse.rgba[i * 4 + 3] = fine.rgba[i * 4 + 3] = 1.0f;
  }
  writeImage(coarse, dir / (stem + "_coarse.png"));
  writeImage(fine, dir / (stem + "_fine.png"));
  std::ostringstream o;
  o << "#declare " << name << "Coarse = function { pigment { image_map { png \"" << stem
    << "_coarse.png\" gamma 1.0 interpolate 2 } } }\n"
    << "#declare " << name << "Fine = function { pigment { image_map { png \"" << stem
    << "_fine.png\" gamma 1.0 interpolate 2 } } }\n"
    << "#declare " << name << " = pigment { average pigment_map {\n"
    << "  [1 rgb " << vec(lo * 7.0) << "]\n";
  static const char* ch[3] = {"red", "green", "blue"};
  for (int c = 0; c < 3; ++c) {
    dvec3 e(0.0);
    e[c] = 7.0 * range[c];
    o << "  [1 function { " << name << "Coarse(x, y, z)." << ch[c] << " } colour_map { [0 rgb 0] [1 rgb "
      << vec(e) << "] }]\n";
    o << "  [1 function { " << name << "Fine(x, y, z)." << ch[c] << " } colour_map { [0 rgb 0] [1 rgb "
      << vec(e / 65535.0) << "] }]\n";
  }
  o << "} }\n";
  return o.str();
}

void writeMesh(std::ostream& o, const TriangleMesh& m, const Scene& s, bool textured,
               const GouraudImage* gouraud, const std::string& gouraud_file,
               bool double_illuminate) {
  o << "mesh2 {\n  vertex_vectors { " << m.positions.size();
  for (const auto& p : m.positions) o << ",\n    " << vec(p);
  o << "\n  }\n";
  // Gouraud needs no normals (its colours are per vertex) and flat shading
  // must not have them (POV-Ray then uses the face normal).
  if (s.shading == ShadingMode::Phong) {
    o << "  normal_vectors { " << m.normals.size();
    for (const auto& n : m.normals) o << ",\n    " << vec(n);
    o << "\n  }\n";
  }
  if (gouraud) {
    o << "  uv_vectors { " << gouraud->uvs.size();
    for (const auto& uv : gouraud->uvs) o << ",\n    " << vec(uv);
    o << "\n  }\n";
  } else if (textured) {
    o << "  uv_vectors { " << m.uvs.size();
    for (const auto& uv : m.uvs) o << ",\n    " << vec(glm::dvec2(uv.x, 1.0 - uv.y));
    o << "\n  }\n";
  }
  o << "  face_indices { " << m.triangles.size();
  for (const auto& t : m.triangles) o << ",\n    <" << t[0] << ", " << t[1] << ", " << t[2] << ">";
  o << "\n  }\n";
  if (gouraud) {
    o << "  uv_indices { " << m.triangles.size();
    for (size_t t = 0; t < m.triangles.size(); ++t)
      o << ",\n    <" << 3 * t << ", " << 3 * t + 1 << ", " << 3 * t + 2 << ">";
    o << "\n  }\n";
    o << "  texture { uv_mapping pigment { " << gouraud_file << " } " << finish(0, 0) << " }\n";
  } else {
    o << "  texture { XvalMaterial }\n";
  }
  o << "  no_shadow\n";
  if (double_illuminate) o << "  double_illuminate\n";
  o << "}\n";
}

}  // namespace

PovExport exportPov(const Scene& scene, const std::filesystem::path& dir, const std::string& output_name) {
  if (scene.render.spp != 1)
    throw ExportError("render.spp = " + std::to_string(scene.render.spp) +
                      ": POV-Ray's antialiasing averages unsaturated samples and the reference "
                      "renderer saturates each sample; export at spp 1");
  std::filesystem::create_directories(dir);
  PovExport ex;
  ex.dir = dir;
  ex.pov = dir / "scene.pov";
  ex.ini = dir / "scene.ini";
  ex.output_name = output_name;

  std::vector<TriangleMesh> meshes;
  for (const auto& o : scene.objects) meshes.push_back(tessellate(o));
  const std::optional<Texture> texture = exportTexture(scene, dir);
  const bool textured = texture.has_value();
  std::vector<LightInfo> lights;
  for (const auto& l : scene.lights)
    if (!std::holds_alternative<AmbientLight>(l)) lights.push_back(info(l));

  std::ostringstream o;
  o << "// Generated by xval export pov. Scene: " << commentSafe(scene.name) << "\n"
    << "// Render from this folder: povray scene.ini (see README.txt).\n"
    << "#version 3.7;\n"
    << "global_settings { assumed_gamma 1.0 max_trace_level 1 }\n"
    << "background { rgbt <0, 0, 0, 1> }\n";
  CameraRays cam(scene.camera);
  o << "camera { perspective location " << vec(cam.origin) << "\n  direction " << vec(cam.forward)
    << "\n  right " << vec(cam.right * (2.0 * cam.tan_half_fov * cam.aspect)) << "\n  up "
    << vec(cam.up * (2.0 * cam.tan_half_fov)) << " }\n";

  std::optional<std::vector<dvec3>> vc;
  Specular sp;
  if (scene.shading == ShadingMode::Gouraud) {
    // Colours computed per vertex by the reference shader; POV-Ray
    // interpolates them across each triangle.
    o << "// Gouraud: per-vertex colours, interpolated by POV-Ray.\n";
  } else {
    if (textured)
      o << "#declare XvalTexture = function { pigment { image_map { png \"texture.png\" gamma 1.0"
        << (scene.material.texture->filter == TextureFilter::Bilinear ? " interpolate 2" : "")
        << " } } }\n";
    Pigment e = std::holds_alternative<YiqLuma>(scene.material.model) ? emissionYiq(scene, lights)
                                                                      : emissionLinear(scene, lights);
    sp = specular(scene, lights);
    for (const auto& ls : sp.light_sources) o << ls << "\n";
    o << "#declare XvalEmission =\n" << toSdl(e, 1) << "\n";
    if (sp.att_texture_map) {
      o << "#declare XvalMaterial = texture { " << *sp.att_texture_map << "\n  texture_map {\n"
        << "    [0 pigment { XvalEmission } " << finish(0, 0) << "]\n"
        << "    [1 pigment { XvalEmission } " << finish(sp.ks, sp.shininess) << "]\n  }\n}\n";
    } else {
      o << "#declare XvalMaterial = texture { pigment { XvalEmission } "
        << finish(sp.ks, sp.shininess) << " }\n";
    }
  }
  for (size_t k = 0; k < meshes.size(); ++k) {
    const TriangleMesh& m = meshes[k];
    if (scene.shading == ShadingMode::Gouraud) {
      Shader<double> shader(scene.material, scene.lights);
      SurfaceColour<double> sc(scene.material, texture ? &*texture : nullptr);
      GouraudImage g = gouraudImage(m, gouraudVertexColours(shader, m, sc, cam.origin));
      const std::string name = "XvalGouraud" + std::to_string(k);
      o << gouraudPigment(g, dir, "gouraud_" + std::to_string(k), name);
      writeMesh(o, m, scene, textured, &g, name, false);
    } else {
      writeMesh(o, m, scene, textured, nullptr, "", sp.ks != 0.0);
    }
  }
  writeFileAtomically(ex.pov, o.str());
  {
    std::ostringstream f;
    f << "; POV-Ray 3.7 options for scene.pov. Run from this folder: povray scene.ini\n"
      << "Input_File_Name=scene.pov\nOutput_File_Name=" << ex.output_name << "\n"
      << "Width=" << scene.camera.width << "\nHeight=" << scene.camera.height << "\n"
      << "; one sample per pixel, through the pixel centre\nAntialias=Off\n"
      << "; 16-bit PNG, linear (no transfer function), alpha = hit mask\n"
      << "Output_File_Type=N\nBits_Per_Color=16\nFile_Gamma=1.0\nOutput_Alpha=On\n"
      << "Display=Off\nPause_When_Done=Off\nVerbose=Off\n";
    writeFileAtomically(ex.ini, f.str());
  }
  {
    std::ostringstream f;
    f << "Exported by xval from scene: " << commentSafe(scene.name) << "\n\n"
      << "Render with POV-Ray 3.7 from this folder:\n\n    povray scene.ini\n\n"
      << "or, equivalently:\n\n    povray +Iscene.pov +O" << ex.output_name << " +W"
      << scene.camera.width << " +H" << scene.camera.height
      << " -A +FN16 +UA File_Gamma=1.0 -D\n\n"
      << "The output holds the model's values linearly (round(v * 65535)), alpha = hit mask.\n";
    writeFileAtomically(dir / "README.txt", f.str());
  }
  return ex;
}

}  // namespace xval
