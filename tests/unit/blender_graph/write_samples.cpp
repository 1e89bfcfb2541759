// Writes the cases of the Blender node-graph check (check_graph.py): for
// every scene of test::shadingCases() and test::lumaOnlyCases(), its glTF export and sample points
// with the colour Shader<double> gives there, as the reference renderer
// shades a hit:
//   phong    N = normalize(N_attr) for a normal N_attr given to the graph's
//            `xval_normal` attribute (arbitrary unit vectors, back-facing
//            ones included), P on a triangle, V = normalize(eye - P);
//   flat     N = normalize(the exported face normal of the triangle);
//   gouraud  the barycentric blend of the reference's vertex colours.
// C is the base colour, or (textured) a colour given to the graph's Image
// Texture node. Every spot light also gets points exactly on its cone,
// where dot(-L, axis) == cos(cutoff) in the reference's own arithmetic (lit:
// the cone test is >=).
//
// Usage: xval_blender_graph_samples OUT_DIR   (writes OUT_DIR/cases.json)
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <optional>

#include "camera/camera.h"
#include "geometry/mesh.h"
#include "gltf/gltf_exporter.h"
#include "shading/flat_normals.h"
#include "shading/shader.h"
#include "shading/surface_colour.h"
#include "support/shading_cases.h"

namespace {

using namespace xval;
using glm::dvec3;
using nlohmann::json;

json vec(dvec3 v) { return json::array({v.x, v.y, v.z}); }
// v rounded to float32, as the glTF buffers hold it (through a volatile, so
// that the optimiser cannot drop the double -> float -> double round trip).
double toFloat(double x) {
  volatile float f = float(x);
  return double(f);
}
dvec3 toFloat(dvec3 v) { return {toFloat(v.x), toFloat(v.y), toFloat(v.z)}; }

// Agreement required of the graph (evaluated in double) with the reference.
// phong / flat: the same operations in another order ((R.V)^n from R.V
// instead of |R - V|): ~1e-13 here; 1e-9 is far below any drift of a
// constant (a luma coefficient changed in its 6th digit moves F by ~1e-6).
// gouraud: the export stores the colours as float32 (relative 6e-8).
constexpr double kGraphTolerance = 1e-9;
constexpr double kGouraudTolerance = 2e-7;

// A point P with dot(-L, axis) == cos_cutoff exactly (L, axis as the
// reference computes them), found by walking along a cone generator.
std::optional<dvec3> onCone(const PreparedLight<double>& l, test::CaseRng& r) {
  const dvec3 a = l.direction;
  const dvec3 any = std::abs(a.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
  const dvec3 u = glm::normalize(glm::cross(a, any)), w = glm::cross(a, u);
  const double s = std::sqrt(std::max(0.0, 1.0 - l.cos_cutoff * l.cos_cutoff));
  for (int tries = 0; tries < 20000; ++tries) {
    const double phi = r.uniform(0, 2.0 * std::numbers::pi);
    const dvec3 g = l.cos_cutoff * a + s * (std::cos(phi) * u + std::sin(phi) * w);
    const dvec3 p = l.position + r.uniform(1.0, 4.0) * g;
    dvec3 L;
    double d;
    towardsLight(l.position - p, L, d);
    if (glm::dot(-L, l.direction) == l.cos_cutoff) return p;
  }
  return std::nullopt;
}

json writeCase(const test::ShadingCase& c, const std::filesystem::path& dir, test::CaseRng& r) {
  const Scene& s = c.scene;
  const GltfExport ex = exportGltf(s, dir / c.name);
  const TriangleMesh mesh = tessellate(s.objects.at(0).shape);
  const Shader<double> shader(s.material, s.lights);
  const dvec3 eye = CameraRays(s.camera).origin;
  const bool textured = s.material.texture.has_value();
  std::optional<Texture> tex;  // only for Gouraud's vertex colours
  if (textured && s.shading == ShadingMode::Gouraud) tex = loadTexture(*s.material.texture);
  const SurfaceColour<double> colour(s.material, tex ? &*tex : nullptr);
  const auto face = flatNormals(mesh);
  std::vector<dvec3> vertex_colours;
  if (s.shading == ShadingMode::Gouraud) vertex_colours = gouraudVertexColours(shader, mesh, colour, eye);

  json samples = json::array();
  auto sample = [&](uint32_t t, dvec3 b, std::optional<dvec3> p_given, bool boundary) {
    const auto& tri = mesh.triangles[t];
    json j;
    j["triangle"] = t;
    j["bary"] = vec(b);
    j["boundary"] = boundary;
    if (s.shading == ShadingMode::Gouraud) {
      j["expected"] = vec(b.x * vertex_colours[tri[0]] + b.y * vertex_colours[tri[1]] +
                          b.z * vertex_colours[tri[2]]);
      samples.push_back(j);
      return;
    }
    const dvec3 p = p_given ? *p_given
                            : b.x * mesh.positions[tri[0]] + b.y * mesh.positions[tri[1]] +
                                  b.z * mesh.positions[tri[2]];
    dvec3 n;
    if (s.shading == ShadingMode::Flat) {
      n = toFloat(face[t]);  // what the glTF holds
      j["face_normal"] = vec(face[t]);
    } else {
      n = toFloat(r.unit());
      j["normal"] = vec(n);
      json corners = json::array();
      for (int k = 0; k < 3; ++k) corners.push_back(vec(toFloat(mesh.normals[tri[k]])));
      j["corner_normals"] = corners;
    }
    const double len = glm::length(n);
    n = len > 0.0 ? n / len : dvec3(0.0);
    const dvec3 col = textured ? toFloat(r.colour()) : s.material.base_color;
    if (textured) j["colour"] = vec(col);
    j["position"] = vec(p);
    j["expected"] = vec(shader.shade(p, n, glm::normalize(eye - p), col));
    samples.push_back(j);
  };
  for (int k = 0; k < 60; ++k) {
    double b1 = r.uniform(0, 1), b2 = r.uniform(0, 1);
    if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
    sample(r.index(uint32_t(mesh.triangles.size())), dvec3(1 - b1 - b2, b1, b2), std::nullopt, false);
  }
  int boundary = 0;
  if (s.shading != ShadingMode::Gouraud)
    for (const auto& l : shader.lights())
      if (l.kind == PreparedLight<double>::Kind::Spot)
        for (int k = 0; k < 4; ++k) {
          const auto p = onCone(l, r);
          if (!p) throw std::runtime_error(c.name + ": no point found exactly on the spot cone");
          sample(r.index(uint32_t(mesh.triangles.size())), dvec3(1.0 / 3), *p, true);
          ++boundary;
        }
  json j;
  j["name"] = c.name;
  j["gltf"] = ex.gltf.string();
  j["tolerance"] = s.shading == ShadingMode::Gouraud ? kGouraudTolerance : kGraphTolerance;
  j["boundary_samples"] = boundary;
  j["samples"] = samples;
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: xval_blender_graph_samples OUT_DIR\n";
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    test::CaseRng r(1313);
    json cases = json::array();
    for (const auto& c : test::shadingCases()) cases.push_back(writeCase(c, dir, r));
    for (const auto& c : test::lumaOnlyCases()) cases.push_back(writeCase(c, dir, r));
    std::ofstream f(dir / "cases.json");
    f << json{{"cases", cases}}.dump();
    if (!f) throw std::runtime_error((dir / "cases.json").string() + ": cannot write");
    std::cout << cases.size() << " cases written to " << (dir / "cases.json").string() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "xval_blender_graph_samples: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
