// The extremes matrix: its scenes, and the per-case measurement of the
// reference renderer (validate/extremes/matrix.h; docs/extremes.md explains every
// case and what it showed).
//
// Conventions of the scenes below (unless a case says otherwise):
//   - camera at distance ~4 looking at the origin, fov 45 deg, size x size
//     pixels, 1 spp (the exporters' condition for exact agreement);
//   - "front" light at (-0.5, 2, 1.25) (the paper's default), "behind" at
//     its reflection through the origin (docs/models.md);
//   - sphere: radius 1, 64 x 32 segments; plane: 2 triangles.
#include "validate/extremes/matrix.h"

#include "files/atomic_write.h"
#include "image/image.h"
#include "image/png_file.h"


#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "geometry/mesh.h"
#include "shading/model/registry.h"

namespace xval::extremes {

using J = nlohmann::ordered_json;

namespace {

constexpr double kPi = 3.14159265358979323846;

J v3(double x, double y, double z) { return J::array({x, y, z}); }
J v3(glm::dvec3 v) { return v3(v.x, v.y, v.z); }

J camera(glm::dvec3 position, glm::dvec3 target, double fov_deg, int size,
         glm::dvec3 up = {0, 1, 0}) {
  return {{"position", v3(position)}, {"target", v3(target)}, {"up", v3(up)},
          {"fov_y_deg", fov_deg},     {"width", size},        {"height", size}};
}

J scene(const std::string& name, J cam, J objects, J material, J lights,
        const char* shading = "phong") {
  return {{"format", "xval-scene/1"}, {"name", name},         {"camera", std::move(cam)},
          {"objects", std::move(objects)}, {"material", std::move(material)},
          {"lights", std::move(lights)},   {"shading", shading},
          {"render", {{"spp", 1}, {"precision", "double"}}}};
}

J sphere(glm::dvec3 centre = {0, 0, 0}, double radius = 1.0) {
  return {{"shape", "sphere"}, {"center", v3(centre)}, {"radius", radius},
          {"segments_longitude", 64}, {"segments_latitude", 32}};
}

J plane(glm::dvec3 centre, glm::dvec3 normal, double side, double uv_repeat = 1.0) {
  return {{"shape", "plane"}, {"center", v3(centre)}, {"normal", v3(normal)},
          {"size", J::array({side, side})}, {"uv_repeat", J::array({uv_repeat, uv_repeat})}};
}

J brick() { return {{"source", "brick"}, {"filter", "bilinear"}}; }

J phong(double n, bool textured = true, glm::dvec3 base = {0.8, 0.6, 0.4}) {
  J m = {{"model", {{"type", ClassicPhong::kName}, {"variant", "paper"}, {"ka", 1}, {"kd", 1},
                    {"ks", 1}, {"shininess", n}}}};
  if (textured) m["texture"] = brick();
  else m["base_color"] = v3(base);
  return m;
}

J yiq(double n = 55, J texture = brick()) {
  return {{"model", {{"type", YiqLuma::kName}, {"kd", 1}, {"ks", 1}, {"shininess", n},
                     {"luma_offset", 0.1}}},
          {"texture", std::move(texture)}};
}

J trilight(glm::dvec3 base) {
  return {{"model", {{"type", Trilight::kName}, {"c0", v3(1.0, 0.85, 0.7)}, {"c1", v3(0.35, 0.5, 0.3)},
                     {"c2", v3(0.2, 0.3, 0.6)}}},
          {"base_color", v3(base)}};
}

J point(glm::dvec3 p) { return {{"type", "point"}, {"position", v3(p)}}; }
J pointAtt(glm::dvec3 p, double c, double l, double q) {
  J j = point(p);
  j["attenuation"] = {{"constant", c}, {"linear", l}, {"quadratic", q}};
  return j;
}
J directional(glm::dvec3 d) { return {{"type", "directional"}, {"direction", v3(d)}}; }
J ambient(double a = 0.1) { return {{"type", "ambient"}, {"color", v3(a, a, a)}}; }

const glm::dvec3 kFront(-0.5, 2.0, 1.25), kBehind(0.5, -2.0, -1.25), kEye(0, 0, 4.2);

// The smallest cook_torrance roughness (alpha) the float path accepts with
// ks = 1, kd = 1 and the lights of the case ct_*_alpha_min (a point light
// of colour 1 and the ambient 0.1: L = 1.1), to two digits: the shading
// bound 4 x 1.1 x (1 + 2.6625 / alpha^3) <= 1e36 (scene_file/
// precision_limits.h) gives alpha >= 2.27e-12; the unit test checks that
// 2.2e-12 is refused.
constexpr double kCookTorranceAlphaMin = 2.3e-12;

// The specular sweep: a brick plane z = 0 seen from (-1,-1,4) with a light
// at the mirror position (1,1,4), so the highlight's peak (R = V) is at
// the image centre. The field of view shrinks with n so the highlight
// fills the frame whatever n: pow(R.V, n) falls to 1/e where the angle
// between R and V is sqrt(2/n), i.e. at about 2.1 sqrt(2/n) on the plane
// (both 4.24 away), and the half-height is set to 2.5 times that:
// tan(fov/2) = 1.25 sqrt(2/n), at most 45 deg.
Case specular(const std::string& label, double n, int size) {
  double fov = 45.0;
  if (n > 0) fov = std::min(45.0, 2.0 * std::atan(1.25 * std::sqrt(2.0 / n)) * 180.0 / kPi);
  Case c;
  c.name = "specular_n" + label;
  c.group = "specular power";
  c.what = "classic Phong, shininess " + label +
           (n == 0 ? ": clamp(R.V)^0 = 1 everywhere (pow(0,0) = 1 where R.V <= 0)"
                   : n >= 1e5 ? ": R.V within 1e-6 of 1 decides the whole highlight (float's "
                                "1 - R.V has an ulp of 6e-8)"
                              : ": highlight at the image centre, fov scaled to its width");
  c.scene = scene(c.name, camera({-1, -1, 4}, {0, 0, 0}, fov, size),
                  J::array({plane({0, 0, 0}, {0, 0, 1}, 8.0, 4.0)}), phong(n),
                  J::array({point({1, 1, 4}), ambient()}));
  return c;
}

// N.L sweeps: a plane facing the camera, lit by a directional light.
Case ndotl(const std::string& name, const std::string& what, glm::dvec3 direction, J material,
           int size) {
  Case c;
  c.name = name;
  c.group = "N.L";
  c.what = what;
  c.scene = scene(name, camera({0, 0, 4}, {0, 0, 0}, 45, size),
                  J::array({plane({0, 0, 0}, {0, 0, 1}, 4.0, 2.0)}), std::move(material),
                  J::array({directional(direction), ambient()}));
  return c;
}

// The scale cases' base: a brick sphere, classic Phong, a point light with
// attenuation 1/(1 + 0.1 d + 0.05 d^2), everything scaled by s about the
// origin (l / s and q / s^2, so the image is the same at every scale).
J scaledScene(const std::string& name, double s, int size) {
  return scene(name, camera(kEye * s, {0, 0, 0}, 45, size), J::array({sphere({0, 0, 0}, s)}),
               phong(55), J::array({pointAtt(kFront * s, 1.0, 0.1 / s, 0.05 / (s * s)), ambient()}));
}

// The vertex of the default sphere nearest to +z (exactly the position the
// renderers trace: float32-rounded).
glm::dvec3 sphereVertexFacingZ() {
  TriangleMesh m = tessellate(UvSphere{});
  glm::dvec3 best = m.positions[0];
  for (const auto& p : m.positions)
    if (p.z > best.z) best = p;
  return best;
}

}  // namespace

std::vector<Case> extremesMatrix(const MatrixOptions& options) {
  const int n = options.size;
  if (n < 8 || n > 4096) throw std::runtime_error("extremes: size must be in [8, 4096]");
  std::vector<Case> out;

  // --- specular power ---------------------------------------------------
  out.push_back(specular("0", 0, n));
  out.push_back(specular("1", 1, n));
  out.push_back(specular("55", 55, n));
  out.push_back(specular("1e3", 1e3, n));
  out.push_back(specular("1e6", 1e6, n));

  // --- N.L ----------------------------------------------------------------
  // Grazing: L = (sqrt(1 - e^2), 0, e), so N.L = e exactly, e = +-5e-8
  // (within 1e-7 of 0); trilight has all three of its terms there.
  for (double e : {5e-8, -5e-8}) {
    const std::string name = e > 0 ? "ndotl_grazing_plus" : "ndotl_grazing_minus";
    out.push_back(ndotl(name,
                        std::string("trilight, directional light with N.L = ") +
                            (e > 0 ? "+" : "-") + "5e-8 on the whole plane: the models' kinks at x = 0",
                        {-std::sqrt(1.0 - e * e), 0.0, -e}, trilight({0.8, 0.7, 0.6}), n));
  }
  out.push_back(ndotl("ndotl_plus_one",
                      "YIQ, brick, directional light along -N: N.L = 1 and R = N exactly, R.V = 1 "
                      "at the image centre",
                      {0, 0, -1}, yiq(), n));
  out.push_back(ndotl("ndotl_minus_one",
                      "YIQ, brick, directional light along +N (from behind): N.L = -1, R = -N",
                      {0, 0, 1}, yiq(), n));

  // --- light distance -----------------------------------------------------
  {
    // The light on a vertex of the sphere facing the camera; the image is
    // odd-sized so the centre pixel's ray passes within 1e-16 of it. The
    // attenuation is nearly 1/d^2 (constant 1e-9). On a convex surface a
    // light on it is below every other point's tangent plane
    // (N.L = -d / 2r), so trilight's back term c2 (d/2) / d^2 diverges as
    // 1/(2d) and its middle term c1 (1 - |x|) / (1e-9 + d^2) as 1/d^2.
    Case c;
    c.name = "light_on_surface";
    c.group = "light distance";
    c.what = "light on a vertex of the sphere, attenuation 1/(1e-9 + d^2): d -> 0 at the centre "
             "pixel (d ~ 1e-16), raw values up to 1e9";
    c.scene = scene(c.name, camera(kEye, {0, 0, 0}, 45, n + 1), J::array({sphere()}),
                    trilight({0.8, 0.7, 0.6}),
                    J::array({pointAtt(sphereVertexFacingZ(), 1e-9, 0.0, 1.0), ambient()}));
    out.push_back(c);
  }
  for (double far : {1e8, 1e20}) {
    Case c;
    c.name = far == 1e8 ? "light_far_1e8" : "light_far_1e20";
    c.group = "light distance";
    c.what = far == 1e8 ? "point light 1e8 away (no attenuation): L is a difference of numbers "
                          "1e8 apart in size"
                        : "point light 1e20 away: |p_light - p|^2 = 1e40 overflows float (max 3.4e38)";
    c.scene = scene(c.name, camera(kEye, {0, 0, 0}, 45, n), J::array({sphere()}), phong(55),
                    J::array({point(glm::normalize(kFront) * far), ambient()}));
    out.push_back(c);
  }

  // --- scale ---------------------------------------------------------------
  {
    Case c{"scale_1", "scale", "the scale cases' base at scale 1: brick sphere, classic Phong, "
                               "point light with attenuation 1/(1 + 0.1 d + 0.05 d^2)",
           scaledScene("scale_1", 1.0, n)};
    out.push_back(c);
    Case s6{"scale_1e-6", "scale", "the base scaled by 1e-6 (attenuation l / s, q / s^2)",
            scaledScene("scale_1e-6", 1e-6, n)};
    out.push_back(s6);
    Case S6{"scale_1e6", "scale", "the base scaled by 1e6 (attenuation l / s, q / s^2)",
            scaledScene("scale_1e6", 1e6, n)};
    out.push_back(S6);
    // The base translated to (1e6, 1e6, 1e6): coordinates 1e6 in size,
    // features of size 1. The float32 ulp there is 0.0625, so the eye and
    // the light are placed on multiples of it (exact in float: the float
    // path's ray origin is not rounded) and the sphere's vertices are
    // rounded to it (the same triangles for every renderer).
    const glm::dvec3 o(1e6, 1e6, 1e6);
    Case off;
    off.name = "offset_1e6";
    off.group = "scale";
    off.what = "the base translated by (1e6, 1e6, 1e6): eye - p and light - p are differences "
               "of float numbers 1e6 in size (ulp 0.0625), the sphere 1 in radius";
    off.scene = scene(off.name, camera(o + glm::dvec3(0, 0, 4.25), o, 45, n),
                      J::array({sphere(o)}), phong(55),
                      J::array({pointAtt(o + kFront, 1.0, 0.1, 0.05), ambient()}));
    out.push_back(off);
  }

  // --- colours ---------------------------------------------------------------
  {
    J palette = {{"source", "image"}, {"path", kPaletteFile}, {"filter", "nearest"}};
    struct C { const char* name; const char* what; bool yiq_model; glm::dvec3 light; };
    for (const C& k : {C{"colours_yiq_front", "YIQ on black, white and the six saturated colours "
                                              "(latitude bands), light in front: C + dY leaves "
                                              "the RGB cube", true, kFront},
                       C{"colours_yiq_behind", "the same, light behind: Y' = 0.1 Y - 0.1 + S, "
                                               "below 0 for every colour", true, kBehind},
                       C{"colours_phong_front", "classic Phong on the same bands, light in front",
                         false, kFront}}) {
      Case c;
      c.name = k.name;
      c.group = "colours";
      c.what = k.what;
      J mat = k.yiq_model ? yiq(55, palette) : phong(55);
      if (!k.yiq_model) mat["texture"] = palette;
      c.scene = scene(c.name, camera(kEye, {0, 0, 0}, 45, n), J::array({sphere()}), mat,
                      J::array({point(k.light), ambient()}));
      out.push_back(c);
    }
  }

  // --- knot -------------------------------------------------------------------
  {
    Case c;
    c.name = "knot_thin_high_pq";
    c.group = "knot";
    c.what = "a (97, 89) torus knot with a tube of radius 0.002 (a sixth of a pixel), 8192 x 8 "
             "segments: high curvature and torsion for the tube frame, sub-pixel triangles";
    J knot = {{"shape", "torus_knot"}, {"p", 97}, {"q", 89}, {"tube_radius", 0.002},
              {"segments_along", 8192}, {"segments_around", 8}};
    c.scene = scene(c.name, camera(kEye, {0, 0, 0}, 45, n), J::array({knot}), yiq(),
                    J::array({point(kFront), ambient()}));
    out.push_back(c);
  }

  // --- degenerate geometry -----------------------------------------------------
  {
    // Tube radius 1e-9 is below the float32 resolution of the centre line
    // (|c| >= 0.55, ulp >= 6e-8): after the rounding every renderer gets,
    // each ring's 9 vertices coincide (or straddle one rounding boundary),
    // so the triangles have zero area or are 1-ulp slivers.
    Case c;
    c.name = "degenerate_knot_collapsed";
    c.group = "degenerate";
    c.what = "knot with tube radius 1e-9: every ring's vertices coincide after float32 rounding, "
             "zero-area triangles (and 1-ulp slivers)";
    J knot = {{"shape", "torus_knot"}, {"tube_radius", 1e-9}, {"segments_along", 768},
              {"segments_around", 8}};
    c.scene = scene(c.name, camera(kEye, {0, 0, 0}, 45, n), J::array({knot}), yiq(),
                    J::array({point(kFront), ambient()}));
    out.push_back(c);
    // A sphere of radius 0.05 at (1e6, 1e6, 1e6): its vertices round to the
    // 0.0625 grid there, onto 19 points: 3920 of its 3968 triangles have
    // zero area, the other 48 are 24 coincident pairs whose (exact, unit)
    // vertex normals differ (which twin a ray hits is decided by rounding).
    const glm::dvec3 o(1e6, 1e6, 1e6);
    Case d;
    d.name = "degenerate_sphere_far";
    d.group = "degenerate";
    d.what = "sphere of radius 0.05 at 1e6: vertices collapse onto 19 points of the 0.0625 "
             "float grid: zero-area triangles and coincident twins with different normals";
    d.scene = scene(d.name, camera(o + glm::dvec3(0.125, 0.0625, 0.375), o, 45, n),
                    J::array({sphere(o, 0.05)}), phong(55, false),
                    J::array({point(o + glm::dvec3(-0.5, 2.0, 1.25)), ambient()}));
    out.push_back(d);
  }

  // --- eye ---------------------------------------------------------------------
  {
    Case c;
    c.name = "light_at_eye";
    c.group = "eye";
    c.what = "point light at the eye: L = V, R.V = 2 (N.V)^2 - 1, the highlight's peak where the "
             "sphere faces the camera";
    c.scene = scene(c.name, camera(kEye, {0, 0, 0}, 45, n), J::array({sphere()}), phong(55),
                    J::array({point(kEye), ambient()}));
    out.push_back(c);
    // The eye on a floor plane (y = 0), looking at a sphere resting on it:
    // every ray starts on the floor, so a ray-triangle test that accepts
    // t = 0 hits the floor at the eye itself (eye - p = 0).
    Case e;
    e.name = "eye_on_surface";
    e.group = "eye";
    e.what = "the eye on the floor plane, a sphere resting on it: every ray starts on a surface "
             "(t = 0 would hit it at the eye, where eye - p = 0)";
    e.scene = scene(e.name, camera({0, 0, 4}, {0, 1, 0}, 45, n),
                    J::array({plane({0, 0, 0}, {0, 1, 0}, 20.0, 10.0), sphere({0, 1, 0})}),
                    phong(55), J::array({point(kFront + glm::dvec3(0, 1, 0)), ambient()}));
    out.push_back(e);
    // The eye exactly on the sphere's +y pole vertex, looking down through
    // the sphere at its inside (lit from within, trilight shows the
    // backs). Every triangle of the polar cap contains the eye: a test that
    // accepts t = 0 hits them at the eye itself, where eye - p is exactly 0
    // in camera-relative coordinates and V = normalize(0).
    for (const char* shading : {"phong", "gouraud"}) {
      Case v;
      v.name = std::string("eye_at_vertex_") + shading;
      v.group = "eye";
      v.what = std::string("the eye on the sphere's pole vertex, ") + shading +
               " shading: the cap's triangles contain the eye (eye - p = 0 at a hit at t = 0)";
      v.scene = scene(v.name, camera({0, 1, 0}, {0, -1, 0}, 45, n, {0, 0, 1}), J::array({sphere()}),
                      trilight({0.8, 0.7, 0.6}), J::array({point({0.3, 0.2, 0.4}), ambient()}),
                      shading);
      out.push_back(v);
    }
  }

  // --- spot cone edge ------------------------------------------------------------
  {
    // A plane facing the camera and a spot at its centre (a corner of the
    // four central pixels) shining along +x with a 45 deg cutoff: the cone
    // meets the plane in the lines y = +-x, x > 0, which pass exactly
    // through the centres of the pixels on the image's diagonals (pixel
    // (i, i) looks at (x, -x)). The spot lies in the plane, so N.L = 0
    // everywhere; hemispherical shading gives (c0 + c2) / 2 inside.
    Case c;
    c.name = "spot_cone_edge";
    c.group = "spot";
    c.what = "hard spot cone whose edge passes exactly through the pixel centres of both image "
             "diagonals (x > 0): lit or not is decided by the last bit";
    J mat = {{"model", {{"type", Hemispherical::kName}, {"c0", v3(1, 1, 1)}, {"c2", v3(0.2, 0.2, 0.2)}}},
             {"base_color", v3(0.9, 0.7, 0.5)}};
    J spot = {{"type", "spot"}, {"position", v3(0, 0, 0)}, {"direction", v3(1, 0, 0)},
              {"cutoff_deg", 45}};
    c.scene = scene(c.name, camera({0, 0, 4}, {0, 0, 0}, 45, n),
                    J::array({plane({0, 0, 0}, {0, 0, 1}, 4.0)}), mat,
                    J::array({spot, ambient()}));
    out.push_back(c);
  }

  // --- issue #33's models: roughness 0 and 1, k near 0, grazing angles ------
  {
    // A sphere lit from the side (L = +x), seen from +z: N.L and N.V both
    // run to 0 at the terminator and the silhouette, where Oren-Nayar
    // divides by max(N.L, N.V) and Minnaert's clamp(N.V)^(k-1) diverges.
    auto sphereCase = [&](const std::string& name, const std::string& what, J model, J light) {
      Case c;
      c.name = name;
      c.group = "issue #33 models";
      c.what = what;
      c.scene = scene(name, camera(kEye, {0, 0, 0}, 45, n), J::array({sphere()}),
                      J{{"model", std::move(model)}, {"base_color", v3(0.8, 0.7, 0.6)}},
                      J::array({std::move(light), ambient()}));
      out.push_back(c);
    };
    const J side = directional({-1, 0, 0});
    for (const char* variant : {"qualitative", "cycles"})
      for (double sigma : {0.0, 1.0})
        sphereCase(std::string("oren_nayar_") + variant + "_sigma" + (sigma == 0.0 ? "0" : "1"),
                   std::string("oren_nayar ") + variant + ", sigma " + (sigma == 0.0 ? "0 (Lambert)" : "1") +
                       ", lit from the side: N.L and N.V -> 0 at the terminator and the silhouette",
                   {{"type", OrenNayar::kName}, {"variant", variant}, {"kd", 1}, {"sigma", sigma}}, side);
    sphereCase("minnaert_k1e-3",
               "minnaert k = 1e-3, lit from the front: clamp(N.V)^(k-1) ~ 1 / N.V grows towards the "
               "silhouette",
               {{"type", Minnaert::kName}, {"kd", 1}, {"k", 1e-3}}, point(kFront));
    sphereCase("blinn_phong_grazing",
               "blinn_phong n = 55, lit from behind: H = normalize(L + V) near the silhouette, where L "
               "and V are nearly opposite and |L + V| -> 0",
               {{"type", BlinnPhong::kName}, {"ka", 1}, {"kd", 1}, {"ks", 1}, {"shininess", 55}}, point(kBehind));
  }

  // --- cook_torrance: alpha near 1 and near 0, grazing angles, Schlick ------
  {
    auto ct = [](const char* d, const char* g, const char* f, double alpha, double kd, double ks) {
      return J{{"type", CookTorrance::kName}, {"distribution", d}, {"geometry", g}, {"fresnel", f},
               {"f0", 0.04}, {"roughness", alpha}, {"kd", kd}, {"ks", ks}};
    };
    auto push = [&](const std::string& name, const std::string& what, J sc) {
      out.push_back(Case{name, "issue #33 models", what, std::move(sc)});
    };
    auto mat = [](J model) { return J{{"model", std::move(model)}, {"base_color", v3(0.8, 0.7, 0.6)}}; };
    const char* vgroove = "cook_torrance";
    // alpha = 1, every D x G: the sphere lit from the side (L = +x), as
    // oren_nayar's cases: N.L -> 0 at the terminator, N.V -> 0 at the
    // silhouette, where the BRDF's 1 / (N.L N.V) would diverge and G / N.V
    // is formed instead (Smith: <= 7.1 / alpha; V-groove: 2 N.H / V.H).
    for (const char* d : {"ggx", "beckmann"})
      for (const char* g : {"smith", vgroove}) {
        const std::string gname = g == vgroove ? "vgroove" : g;
        const std::string name = std::string("ct_") + d + "_" + gname + "_alpha1";
        push(name,
             std::string("cook_torrance ") + d + " / " + g + ", alpha 1, lit from the side: N.L and N.V -> 0 "
                 "at the terminator and the silhouette (G / N.V formed, never 1 / (N.L N.V))",
             scene(name, camera(kEye, {0, 0, 0}, 45, n), J::array({sphere()}), mat(ct(d, g, "none", 1.0, 1, 1)),
                   J::array({directional({-1, 0, 0}), ambient()})));
      }
    // alpha near 0: the specular sweep's mirror plane (eye (-1,-1,4),
    // light (1,1,4): H = N at the image centre), the field of view scaled
    // so that the lobe (where tan(N, H) = 2 alpha D is 1/25 of its peak
    // (GGX), e^-4 (Beckmann); on the plane ~ 4.24 x 2 alpha from the
    // centre) fills the frame:
    // tan(fov/2) = 3 alpha. ks = 0.9 x 4 alpha^2 N.V puts the peak
    // S = 1 / (4 alpha^2 N.V) (D = 1 / (pi alpha^2), G ~ 1) at 0.9, below
    // the saturation. tan^2 ~ alpha^2 = 1e-6 there: in float, 1 - (N.H)^2
    // would cancel to an error of 1e-7 / 1e-6 (the cross product does not).
    const double nv_mirror = 4.0 / std::sqrt(18.0), alpha_small = 1e-3;
    for (const char* d : {"ggx", "beckmann"}) {
      const std::string name = std::string("ct_") + d + "_alpha1e-3";
      const double fov = 2.0 * std::atan(3.0 * alpha_small) * 180.0 / kPi;
      J model = ct(d, "smith", "none", alpha_small, 0, 0.9 * 4.0 * alpha_small * alpha_small * nv_mirror);
      push(name,
           std::string("cook_torrance ") + d + " / smith, alpha 1e-3 (near 0): the peak's tan^2 ~ alpha^2 = 1e-6 "
               "at the image centre, fov scaled to the lobe, ks so the peak is 0.9",
           scene(name, camera({-1, -1, 4}, {0, 0, 0}, fov, n), J::array({plane({0, 0, 0}, {0, 0, 1}, 8.0, 4.0)}),
                 mat(std::move(model)), J::array({point({1, 1, 4}), ambient()})));
    }
    // The smallest alpha float accepts with ks = 1 (scene_file/
    // precision_limits.h: the shading bound B = 4 C K F L M <= 1e36 with
    // K = kd + ks specularGain(), specularGain ~ 2.66 / alpha^3 for Smith,
    // L = 1.1 here: alpha >= 2.3e-12), on a plane seen head-on with the
    // light at the eye; the image is odd-sized, so the centre pixel's ray
    // is -z and hits the origin: N = L = V exactly, sin^2(N, H) = 0, and D
    // is at its peak 1 / (pi alpha^2) ~ 6e22 (GGX formed as alpha^2 /
    // (pi q^2), q = alpha^2, squared q to 2.8e-47, below float's smallest
    // subnormal: D = inf, a raw Inf pixel; models::microfacetD now forms
    // (alpha / q)^2 / pi). Every other pixel is 0.005 rad or more off the
    // lobe.
    for (const char* d : {"ggx", "beckmann"}) {
      const std::string name = std::string("ct_") + d + "_alpha_min";
      push(name,
           std::string("cook_torrance ") + d + " / smith, alpha 2.3e-12 (the smallest float accepts with "
               "ks = 1), light at the eye: N = L = V at the centre pixel, "
               "D = 1 / (pi alpha^2) ~ 6e22",
           scene(name, camera({0, 0, 4}, {0, 0, 0}, 45, n + 1), J::array({plane({0, 0, 0}, {0, 0, 1}, 4.0)}),
                 mat(ct(d, "smith", "none", kCookTorranceAlphaMin, 1, 1)),
                 J::array({point({0, 0, 4}), ambient()})));
    }
    // Grazing on both sides, Schlick's F at grazing: a plane z = 0 seen
    // from 0.01 above it, nearly along +y (fov 0.6 deg), with a directional
    // light low over the far side (elevation 2e-4 rad, travelling towards
    // -y): the forward-scattering peak, H ~ N, at the rows whose view
    // elevation e_v is 2e-4. There N.L = 2e-4, N.V = e_v (5e-5 to 1e-2
    // over the rows), V.H ~ (2e-4 + e_v) / 2 ~ 1e-4 .. 5e-3, so Schlick's
    // F = f0 + (1 - f0)(1 - V.H)^5 ~ 1 and the V-groove's 2 N.H / V.H
    // reaches its floor V.H >= 2^-10 (models::vGrooveGOverNv) in the rows
    // nearest the horizon. H = (L + V) / |L + V| turns an error in V into
    // one 1 / |L + V| (up to 5000) times larger in H: the plane is 2.5 wide
    // (it still fills the 0.6 deg view) and 200 long, because the float
    // path's hit point, interpolated over a triangle 200 wide, is off
    // sideways by a few ulps of 200, and that, so amplified, moved the
    // lobe's flanks by 150/65535 (alpha 0.25) against double: a precision
    // limit of the float geometry, not of the model. alpha 0.5; ks puts
    // the peaks near 0.7 (V-groove: G / N.V up to 2 / 2^-10 = 2048;
    // Smith: G1(N.L) ~ 2 N.L / alpha keeps S near 3e-3 per unit ks).
    const double e_light = 2e-4;
    struct G { const char* d; const char* g; double ks; };
    for (const G& k : {G{"beckmann", vgroove, 3e-4}, G{"ggx", "smith", 200.0}}) {
      const std::string name = std::string("ct_") + k.d + "_" + (k.g == vgroove ? "vgroove" : k.g) + "_schlick_grazing";
      push(name,
           std::string("cook_torrance ") + k.d + " / " + k.g + " / schlick, alpha 0.5, eye and light 5e-5 to "
               "1e-2 rad above a plane on opposite sides: N.L, N.V and V.H -> 0 together (the V-groove's V.H "
               "floor 2^-10, Schlick's F -> 1)",
           scene(name, camera({0, -10, 0.01}, {0, 90, 0.01 - 100 * 0.004}, 0.6, n),
                 J::array({J{{"shape", "plane"}, {"center", v3(0, 90, 0)}, {"normal", v3(0, 0, 1)},
                             {"size", J::array({2.5, 200.0})}}}),
                 mat(ct(k.d, k.g, "schlick", 0.5, 0, k.ks)),
                 J::array({directional({0, -std::cos(e_light), -std::sin(e_light)}), ambient()})));
    }
  }
  return out;
}

void writePaletteTexture(const std::filesystem::path& file) {
  // White, black, red, green, blue, cyan, magenta, yellow, top to bottom.
  const unsigned char px[8][3] = {{255, 255, 255}, {0, 0, 0},     {255, 0, 0},   {0, 255, 0},
                                  {0, 0, 255},     {0, 255, 255}, {255, 0, 255}, {255, 255, 0}};
  const std::string png = encodePng(1, 8, 3, 8, px, {}, file.string());
  requirePngDecodable(png, file.string(), 1, 8);
  writeFileAtomically(file, png);
}

std::vector<std::filesystem::path> writeCaseScenes(const std::vector<Case>& cases,
                                                   const std::filesystem::path& scenes_dir) {
  std::filesystem::create_directories(scenes_dir);
  writePaletteTexture(scenes_dir / kPaletteFile);
  std::vector<std::filesystem::path> files;
  for (const Case& c : cases) {
    const std::filesystem::path f = scenes_dir / (c.name + ".json");
    writeFileAtomically(f, c.scene.dump(2) + "\n");
    files.push_back(f);
  }
  return files;
}

std::vector<Case> selectCases(const std::vector<Case>& all, const std::string& only) {
  if (only.empty()) return all;
  std::set<std::string> want;
  std::stringstream ss(only);
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) want.insert(item);
  std::vector<Case> cases;
  for (const auto& c : all)
    if (want.erase(c.name)) cases.push_back(c);
  if (!want.empty()) {
    std::string names;
    for (const auto& c : all) names += " " + c.name;
    throw std::runtime_error("--only: no case named " + *want.begin() + "; the cases are:" + names);
  }
  return cases;
}

}  // namespace xval::extremes
