// Scene warnings (scene_lint.h states each rule and its reason).
#include "lint/scene_lint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>

#include "geometry/closed_surface.h"
#include "geometry/scene_meshes.h"
#include "render/ray_triangle.h"

namespace xval {

namespace {

using glm::dvec3;

std::string lightName(size_t i) { return "lights[" + std::to_string(i) + "]"; }

// "objects[K]", and the primitive when the object has several meshes.
std::string meshName(const SceneMeshes& sm, size_t i) {
  const size_t k = sm.object[i];
  size_t first = i, count = 0;
  while (first > 0 && sm.object[first - 1] == k) --first;
  for (size_t j = first; j < sm.object.size() && sm.object[j] == k; ++j) ++count;
  std::string name = "objects[" + std::to_string(k) + "]";
  if (count > 1) name += " (primitive " + std::to_string(i - first) + ")";
  return name;
}

const char* kindOf(const Light& l) {
  if (std::holds_alternative<PointLight>(l)) return "point";
  if (std::holds_alternative<SpotLight>(l)) return "spot";
  if (std::holds_alternative<DirectionalLight>(l)) return "directional";
  return "ambient";
}

dvec3 colourOf(const Light& l) {
  return std::visit([](const auto& x) { return x.color; }, l);
}

std::optional<dvec3> positionOf(const Light& l) {
  if (const auto* p = std::get_if<PointLight>(&l)) return p->position;
  if (const auto* s = std::get_if<SpotLight>(&l)) return s->position;
  return std::nullopt;
}

// The mesh with vertices of equal position made one (the lowest index):
// the built-in shapes repeat a vertex along their uv seams and at a
// sphere's poles, so by index they are open; welded, the closed-surface
// conditions see the surface as drawn. Exact equality: the surface (the
// set of points the triangles cover) is unchanged.
TriangleMesh weldedByPosition(const TriangleMesh& mesh) {
  std::vector<uint32_t> order(mesh.positions.size());
  for (uint32_t v = 0; v < order.size(); ++v) order[v] = v;
  auto less = [&](uint32_t a, uint32_t b) {
    const dvec3 p = mesh.positions[a], q = mesh.positions[b];
    return p.x != q.x ? p.x < q.x : p.y != q.y ? p.y < q.y : p.z != q.z ? p.z < q.z : a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<uint32_t> same(order.size());
  for (size_t k = 0; k < order.size(); ++k)
    same[order[k]] = k > 0 && mesh.positions[order[k]] == mesh.positions[order[k - 1]] ? same[order[k - 1]] : order[k];
  TriangleMesh out;
  out.positions = mesh.positions;
  out.triangles.reserve(mesh.triangles.size());
  for (const glm::u32vec3& t : mesh.triangles) out.triangles.push_back({same[t[0]], same[t[1]], same[t[2]]});
  return out;
}

bool isOutwardSolid(const TriangleMesh& mesh) { return whyNotAnOutwardSolid(weldedByPosition(mesh)).empty(); }

// The winding number's half of the inside test: within 0.25 of an integer
// n >= 1 (a point on the surface has a half-integer one).
bool windingSaysInside(const TriangleMesh& mesh, dvec3 x) {
  const double w = windingNumber(mesh, x);
  const double n = std::round(w);
  return n >= 1.0 && std::abs(w - n) < 0.25;
}

// The meshes' "is an outward solid" answers, computed once and only for a
// mesh some point is found inside of (whyNotAnOutwardSolid is the dear part).
struct SolidMemo {
  const SceneMeshes& sm;
  std::vector<std::optional<bool>> solid;
  explicit SolidMemo(const SceneMeshes& s) : sm(s), solid(s.meshes.size()) {}
  bool isSolid(size_t i) {
    if (!solid[i]) solid[i] = isOutwardSolid(sm.meshes[i]);
    return *solid[i];
  }
  // The first mesh x is strictly inside of (see strictlyInsideClosedMesh).
  std::optional<size_t> enclosing(dvec3 x) {
    for (size_t i = 0; i < sm.meshes.size(); ++i)
      if (windingSaysInside(sm.meshes[i], x) && isSolid(i)) return i;
    return std::nullopt;
  }
};

}  // namespace

std::string describe(const SceneWarning& w) { return w.subject + ": " + w.message + " [" + w.code + "]"; }

std::string warningLine(const Scene& scene, const SceneWarning& w) {
  return "warning: " + scene.name + ": " + describe(w);
}

std::vector<SceneWarning> printSceneWarnings(const char* prefix, const Scene& scene) {
  std::vector<SceneWarning> ws = lintScene(scene);
  for (const SceneWarning& w : ws) std::fprintf(stderr, "%s: %s\n", prefix, warningLine(scene, w).c_str());
  return ws;
}

double windingNumber(const TriangleMesh& mesh, dvec3 x) {
  // Each triangle's signed solid angle seen from x (Van Oosterom and
  // Strackee): tan(Omega / 2) = a . (b x c) / (|a||b||c| + (a.b)|c| +
  // (a.c)|b| + (b.c)|a|), a, b, c the corners relative to x; positive for
  // a triangle wound counter-clockwise seen from outside with x inside.
  double sum = 0.0;
  for (const glm::u32vec3& t : mesh.triangles) {
    const dvec3 a = mesh.positions[t[0]] - x, b = mesh.positions[t[1]] - x, c = mesh.positions[t[2]] - x;
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double num = glm::dot(a, glm::cross(b, c));
    const double den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    sum += 2.0 * std::atan2(num, den);
  }
  return sum / (4.0 * std::numbers::pi);
}

bool strictlyInsideClosedMesh(const TriangleMesh& mesh, dvec3 x) {
  return windingSaysInside(mesh, x) && isOutwardSolid(mesh);
}

bool spotConeFallsBetweenVertices(const SpotLight& spot, const TriangleMesh& mesh) {
  const dvec3 axis = glm::normalize(spot.direction);
  const double cos_cutoff = std::cos(spot.cutoff_deg * std::numbers::pi / 180.0);
  // The axis ray's hits where per-pixel shading lights the surface: the
  // interpolated normal faces the light, n . (x - p) > 0, i.e. n . axis < 0.
  const RayShear ray(spot.position, axis);
  bool lit_hit = false;
  for (const glm::u32vec3& t : mesh.triangles) {
    TriangleHit h;
    if (!intersectTriangle(ray, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]], 0.0,
                           std::numeric_limits<double>::infinity(), h))
      continue;
    const dvec3 n = (1.0 - h.b1 - h.b2) * mesh.normals[t[0]] + h.b1 * mesh.normals[t[1]] + h.b2 * mesh.normals[t[2]];
    if (glm::dot(n, axis) < 0.0) {
      lit_hit = true;
      break;
    }
  }
  if (!lit_hit) return false;
  std::vector<char> in_cone(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const dvec3 d = mesh.positions[v] - spot.position;
    const double len = glm::length(d);
    in_cone[v] = len > 0.0 && glm::dot(d, axis) >= cos_cutoff * len;  // the shader's test, lights.h
  }
  for (const glm::u32vec3& t : mesh.triangles)
    if (in_cone[t[0]] && in_cone[t[1]] && in_cone[t[2]]) return false;
  return true;
}

std::vector<SceneWarning> lintScene(const Scene& scene) {
  std::vector<SceneWarning> out;
  const SceneMeshes sm = sceneMeshes(scene);
  SolidMemo memo(sm);
  for (size_t l = 0; l < scene.lights.size(); ++l) {
    const std::optional<dvec3> at = positionOf(scene.lights[l]);
    if (!at) continue;
    if (const std::optional<size_t> i = memo.enclosing(*at))
      out.push_back({"light_inside_closed_mesh", lightName(l),
                     std::string("the ") + kindOf(scene.lights[l]) + " light is inside the closed surface of " +
                         meshName(sm, *i) +
                         ": it reaches that surface only from behind (N.L < 0 where it first meets it), and lights "
                         "whatever faces it only through the surface's walls (no shadows)"});
  }
  if (const std::optional<size_t> i = memo.enclosing(scene.camera.position))
    out.push_back({"camera_inside_closed_mesh", "camera",
                   "the camera is inside the closed surface of " + meshName(sm, *i) +
                       ": it sees only that surface's inside (its back faces) and what is enclosed with it"});
  if (scene.shading == ShadingMode::Gouraud)
    for (size_t l = 0; l < scene.lights.size(); ++l) {
      const auto* spot = std::get_if<SpotLight>(&scene.lights[l]);
      if (!spot) continue;
      for (size_t i = 0; i < sm.meshes.size(); ++i)
        if (spotConeFallsBetweenVertices(*spot, sm.meshes[i]))
          out.push_back({"gouraud_spot_between_vertices", lightName(l),
                         "under gouraud shading the spot cone hits " + meshName(sm, i) +
                             " but holds no whole triangle of it: the lit disc shows only as ramps between "
                             "vertices, or not at all (use phong shading or a finer mesh)"});
    }
  for (size_t l = 0; l < scene.lights.size(); ++l)
    if (colourOf(scene.lights[l]) == dvec3(0.0))
      out.push_back({"light_adds_nothing", lightName(l),
                     std::string("the ") + kindOf(scene.lights[l]) + " light's colour is (0, 0, 0): it adds nothing"});
  return out;
}

}  // namespace xval
