#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <variant>

#include "camera/camera.h"
#include "camera/triangle_edge.h"
#include "geometry/front_faces.h"
#include "image/pixel_classes.h"
#include "geometry/mesh.h"
#include "geometry/model_textures.h"
#include "process/job_pool.h"
#include "geometry/scene_meshes.h"
#include "render/accel.h"
#include "render/precision_probe.h"
#include "render/raster.h"
#include "scene_file/precision_limits.h"
#include "shading/batch_shader.h"
#include "shading/flat_normals.h"
#include "shading/shader.h"
#include "shading/surface_colour.h"
#include "texture/mip_chain.h"
#include "texture/texture.h"

namespace xval {

RenderOptions defaultOptions(const Scene& scene) {
  RenderOptions o;
  o.spp = scene.render.spp;
  o.precision = scene.render.precision;
  return o;
}

std::string describeVisibility(const RenderStats& stats) {
  std::string s = stats.visibility;
  if (stats.culled_triangles) s += ", " + std::to_string(stats.culled_triangles) + " back faces skipped";
  return s + "; shading: " + stats.shading;
}

namespace {

// Runs `threads` copies of worker side by side in the job pool
// (process/job_pool.h) and waits for all. A worker is one thread's loop,
// not one work item: it owns its scratch buffers (a band's rows, a tile's
// hits) for the whole frame and takes the bands or tiles, in order, from a
// shared counter. An exception in a worker is rethrown here once every
// thread has joined (a bare std::thread would terminate the process).
template <class F> void runOnThreads(int threads, F& worker) {
  runJobPool(size_t(std::max(1, threads)), threads, [&](size_t) { worker(); });
}

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

constexpr int kTile = 8;  // tile side in pixels; a multiple of kPacketSide
constexpr int kBand = 16;  // rows per band of the rasterised path
static_assert(kTile % Accel::kPacketSide == 0);

// A mesh's attributes converted once to the working precision T.
template <class T> struct ShadedMesh {
  using V = glm::vec<3, T>;
  const TriangleMesh* src;
  size_t object = 0;  // the scene object: its material's shader and colour
  std::vector<V> p, n, face_n, vertex_colour;
  std::vector<glm::vec<2, T>> uv;
};

template <class T>
ShadedMesh<T> prepareMesh(const TriangleMesh& m, ShadingMode mode, const Shader<T>& shader,
                          const SurfaceColour<T>& colour, glm::dvec3 eye) {
  ShadedMesh<T> s;
  s.src = &m;
  s.p.reserve(m.positions.size());
  for (auto& v : m.positions) s.p.emplace_back(v - eye);  // camera-relative (Shading)
  for (auto& v : m.normals) s.n.emplace_back(v);
  for (auto& v : m.uvs) s.uv.emplace_back(v);
  if (mode == ShadingMode::Flat)
    for (const glm::dvec3& g : flatNormals(m)) s.face_n.emplace_back(g);
  if (mode == ShadingMode::Gouraud) s.vertex_colour = gouraudVertexColours(shader, m, colour, eye);
  return s;
}

// The hit's texture coordinate, wrapped: frac(uv0) + b1 (uv1 - uv0) +
// b2 (uv2 - uv0). Mathematically b0 uv0 + b1 uv1 + b2 uv2 up to a whole
// number of texture repeats, which the wrap ignores; numerically its
// magnitude stays ~1 instead of reaching the repeat count (12 along the
// paper's knot), so in float the lookup moves by ~1 ulp of 1 (3e-5 of a
// 512-texel texture) instead of ~1 ulp of 12.
template <class T>
glm::vec<2, T> interpolateUv(const std::vector<glm::vec<2, T>>& uv, const glm::u32vec3& tri, T b1, T b2) {
  const glm::vec<2, T> u0 = uv[tri[0]];
  return (u0 - glm::floor(u0)) + b1 * (uv[tri[1]] - u0) + b2 * (uv[tri[2]] - u0);
}

// |cos| between a ray and the hit triangle's plane normal.
double geometricIncidence(const TriangleMesh& m, const glm::u32vec3& t, glm::dvec3 dir) {
  glm::dvec3 g = glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
  double len = glm::length(g);
  return len > 0.0 ? std::abs(glm::dot(g / len, dir)) : 0.0;
}

// The derivatives of the hit's uv along the image's x and y, per `step`
// pixels (the sample grid's spacing), from the camera ray's differentials:
// duv = db1 (uv1 - uv0) + db2 (uv2 - uv0), db from barycentricDerivatives
// (render/precision_probe.h). In double from the world-space mesh,
// whatever the shading precision.
struct UvFootprint {
  glm::dvec2 dx{0}, dy{0};
};
UvFootprint uvFootprint(const CameraRays& cam, const TriangleMesh& m, const glm::u32vec3& tri, double b1, double b2,
                        double step) {
  const glm::dvec3 P[3] = {m.positions[tri[0]], m.positions[tri[1]], m.positions[tri[2]]};
  const BarycentricDerivatives d = barycentricDerivatives(cam, P, b1, b2, step);
  const glm::dvec2 du1 = m.uvs[tri[1]] - m.uvs[tri[0]], du2 = m.uvs[tri[2]] - m.uvs[tri[0]];
  return {d.dx.x * du1 + d.dx.y * du2, d.dy.x * du1 + d.dy.y * du2};
}

// Everything the per-sample work needs in precision T. One shader and
// surface colour per scene object (its material: materialOf).
template <class T> struct Shading {
  using V = glm::vec<3, T>;
  std::vector<Shader<T>> shaders;
  std::vector<SurfaceColour<T>> colours;
  ShadingMode mode;
  bool normalize_normal = true;  // phong: normalize(sum b_k N_k), else the sum as it is
  CameraRays cam;                // for the trilinear filter's footprint (uvFootprint)
  // Shading coordinates are camera-relative: every position minus the eye,
  // subtracted in double before the rounding to T (shading/shader.h), so
  // the eye is the origin and a float surface point keeps float's relative
  // precision of its distance from the eye wherever the scene is
  // (docs/extremes.md, offset_1e6).
  V eye{0};
  std::vector<ShadedMesh<T>> meshes;

  // textures[k]: object k's texture (null: none); mesh_object[i]: the
  // object of src[i].
  Shading(const Scene& scene, const std::vector<TriangleMesh>& src, const std::vector<size_t>& mesh_object,
          const std::vector<const Texture*>& textures, const std::vector<const MipChain*>& chains)
      : mode(scene.shading), normalize_normal(scene.normalize_normal), cam(scene.camera) {
    const glm::dvec3 eye_world = cam.origin;
    for (size_t k = 0; k < scene.objects.size(); ++k) {
      shaders.emplace_back(materialOf(scene, k), scene.lights, eye_world);
      shaders.back().unitReflection(!scene.normalize_normal);  // the listing's normalize(R)
      colours.emplace_back(materialOf(scene, k), textures[k], chains[k]);
    }
    for (size_t i = 0; i < src.size(); ++i) {
      const size_t k = mesh_object[i];
      meshes.push_back(prepareMesh<T>(src[i], scene.shading, shaders[k], colours[k], eye_world));
      meshes.back().object = k;
    }
  }
};

// ---- Accumulation: what a hit contributes to its pixel ----------------------

// What a precision probe changes in a hit's shading (render/
// precision_probe.h); the default changes nothing, so a probe with it is
// the sample's own colour bit for bit.
template <class T> struct ShadingNudge {
  using V = glm::vec<3, T>;
  glm::vec<2, T> duv{0};  // added to the interpolated uv
  double dlambda = 0.0;   // added to a trilinear texture's level, clamped to its chain
  bool flip = false;      // N -> -N
  bool turn = false;      // N -> turn_cos N + turn_sin (turn_axis x N)
  V turn_axis{0};
  T turn_cos = 1, turn_sin = 0;
};

// A trilinear texture's level of detail at the hit: its footprint per
// `step` pixels (uvFootprint).
template <class T> double hitLambda(const Shading<T>& sh, const Hit& h, double step) {
  const ShadedMesh<T>& m = sh.meshes[h.mesh];
  const UvFootprint f = uvFootprint(sh.cam, *m.src, m.src->triangles[h.triangle], h.b1, h.b2, step);
  return sh.colours[m.object].mips->lambda(f.dx, f.dy);
}

// The surface colour C of a hit at its wrapped uv; a trilinear texture at
// the level of the hit's footprint per `step` pixels (hitLambda), moved by
// dlambda within the chain's levels.
template <class T>
glm::vec<3, T> hitColour(const Shading<T>& sh, const Hit& h, glm::vec<2, T> uv, double step, double dlambda = 0.0) {
  const SurfaceColour<T>& colour = sh.colours[sh.meshes[h.mesh].object];
  if (!colour.usesFootprint()) return colour.at(uv);
  const double lambda = hitLambda(sh, h, step);
  if (dlambda == 0.0) return colour.at(uv, lambda);
  return colour.at(uv, std::clamp(lambda + dlambda, 0.0, double(colour.mips->maxLevel())));
}

// What shadeHit computes from a (non-Gouraud) hit before the model runs:
// the point p = sum b_k P_k, the shading normal (Phong: normalize(sum b_k
// N_k), zero stays zero, or with normalize_normal off the sum itself; flat:
// the face normal), the eye vector v and the wrapped uv.
template <class T> struct HitSurface {
  glm::vec<3, T> p, nrm, v;
  glm::vec<2, T> uv;
};
template <class T> HitSurface<T> hitSurface(const Shading<T>& sh, const Hit& h) {
  using V = glm::vec<3, T>;
  const ShadedMesh<T>& m = sh.meshes[h.mesh];
  const auto& tri = m.src->triangles[h.triangle];
  const T b1 = T(h.b1), b2 = T(h.b2), b0 = T(1) - b1 - b2;
  HitSurface<T> s;
  s.p = b0 * m.p[tri[0]] + b1 * m.p[tri[1]] + b2 * m.p[tri[2]];
  if (sh.mode == ShadingMode::Flat) {
    s.nrm = m.face_n[h.triangle];
  } else {
    s.nrm = b0 * m.n[tri[0]] + b1 * m.n[tri[1]] + b2 * m.n[tri[2]];
    if (sh.normalize_normal) {
      T len = glm::length(s.nrm);
      s.nrm = len > T(0) ? s.nrm / len : V(0);  // zero-length normals stay 0
    }
  }
  s.uv = interpolateUv(m.uv, tri, b1, b2);
  s.v = glm::normalize(sh.eye - s.p);
  return s;
}

// The unsaturated colour c of one hit: the model at its HitSurface, texture
// colour at the wrapped uv (hitColour, per `step` pixels); Gouraud: sum b_k
// of the vertex colours. backfacing: the shading normal faces away from the
// eye, N . (eye - p) < 0 (always false for Gouraud). nudge: a probe's
// change of N, uv or the level (none for Gouraud, whose model ran at the
// vertices).
template <class T>
__attribute__((flatten)) glm::vec<3, T> shadeHit(const Shading<T>& sh, const Hit& h, double step, bool& backfacing,
                                                 const ShadingNudge<T>* nudge = nullptr) {
  const ShadedMesh<T>& m = sh.meshes[h.mesh];
  if (sh.mode == ShadingMode::Gouraud) {
    const auto& tri = m.src->triangles[h.triangle];
    const T b1 = T(h.b1), b2 = T(h.b2), b0 = T(1) - b1 - b2;
    backfacing = false;
    return b0 * m.vertex_colour[tri[0]] + b1 * m.vertex_colour[tri[1]] + b2 * m.vertex_colour[tri[2]];
  }
  HitSurface<T> s = hitSurface(sh, h);
  backfacing = glm::dot(s.nrm, s.v) < T(0);
  if (!nudge) return sh.shaders[m.object].shade(s.p, s.nrm, s.v, hitColour(sh, h, s.uv, step));
  if (nudge->flip) s.nrm = -s.nrm;
  if (nudge->turn) s.nrm = nudge->turn_cos * s.nrm + nudge->turn_sin * glm::cross(nudge->turn_axis, s.nrm);
  s.uv += nudge->duv;
  return sh.shaders[m.object].shade(s.p, s.nrm, s.v, hitColour(sh, h, s.uv, step, nudge->dlambda));
}

// A (non-Gouraud) hit shaded in parts, for its probes: shadeHit's surface
// s, backfacing flag and surface colour C, the lights sampled at s.p
// (into `lights`, Shader::sampleLights) and their sums, and c =
// shadeWith(sums, C): shadeHit's colour bit for bit (the same operations).
template <class T> struct HitParts {
  HitSurface<T> s;
  glm::vec<3, T> C{0}, c{0};
  typename Shader<T>::LightSums sums;
  bool backfacing = false;
};
template <class T>
HitParts<T> shadeHitParts(const Shading<T>& sh, const Hit& h, double step, std::vector<LightSample<T>>& lights) {
  const Shader<T>& shader = sh.shaders[sh.meshes[h.mesh].object];
  HitParts<T> out;
  out.s = hitSurface(sh, h);
  out.backfacing = glm::dot(out.s.nrm, out.s.v) < T(0);
  out.C = hitColour(sh, h, out.s.uv, step);
  shader.sampleLights(out.s.p, lights);
  out.sums = shader.lit(lights, out.s.nrm, out.s.v);
  out.c = shader.shadeWith(out.sums, out.C);
  return out;
}

// The precision probes of one sample (render/precision_probe.h): the
// largest channel change of its saturated colour c under each probe, and
// its saturated colour with N turned around (when backfacing: shadeHit's
// flag for it). at: the sample's image point; n: samples per pixel side;
// parts, lights: the sample's shadeHitParts (null for Gouraud).
template <class T> struct SampleProbes {
  double position = 0.0, uv = 0.0, normal = 0.0;
  glm::vec<3, T> flipped{0};
};
template <class T>
SampleProbes<T> probeSample(const Shading<T>& sh, const Hit& h, double step, glm::vec<3, T> c, bool backfacing,
                            glm::dvec2 at, int n, const HitParts<T>* parts, const std::vector<LightSample<T>>& lights) {
  using V = glm::vec<3, T>;
  SampleProbes<T> out;
  const ShadedMesh<T>& m = sh.meshes[h.mesh];
  const auto& tri = m.src->triangles[h.triangle];
  bool back = false;
  auto change = [&](const Hit& hh, const ShadingNudge<T>* nudge) {
    return double(largestChannelDifference(models::saturate(shadeHit(sh, hh, step, back, nudge)), c));
  };
  // Position: the hit moved along x and y on its triangle's plane.
  const glm::dvec3 P[3] = {m.src->positions[tri[0]], m.src->positions[tri[1]], m.src->positions[tri[2]]};
  const BarycentricDerivatives d = barycentricDerivatives(sh.cam, P, h.b1, h.b2, kPositionStepPixels);
  for (const glm::dvec2 db : {d.dx, -d.dx, d.dy, -d.dy}) {
    Hit moved = h;
    moved.b1 += db.x, moved.b2 += db.y;
    if (std::isfinite(moved.b1) && std::isfinite(moved.b2)) out.position = std::max(out.position, change(moved, nullptr));
  }
  if (sh.mode == ShadingMode::Gouraud) return out;  // the model ran at the vertices: no uv, N or flip here
  // The probes below change N, uv or the level at the hit itself: its
  // surface, the colour where uv and level stay and the lights' samples
  // come from the sample's own shading (parts), and each is shaded as
  // shadeHit with the nudge would (the same operations).
  const HitSurface<T>& s = parts->s;
  const Shader<T>& shader = sh.shaders[m.object];
  const V& C = parts->C;
  auto changeAt = [&](const V& nrm, const V& colour) {
    return double(largestChannelDifference(models::saturate(shader.shadeWith(shader.lit(lights, nrm, s.v), colour)), c));
  };
  if (backfacing) out.flipped = models::saturate(shader.shadeWith(shader.lit(lights, -s.nrm, s.v), C));
  // uv: one 1/256 texel of level 0 along u and v; a trilinear level by its
  // quad estimate's difference.
  const SurfaceColour<T>& colour = sh.colours[m.object];
  if (colour.texture) {
    // Only the surface colour changes: the sample's own sums serve
    // (Shader::lit; shadeWith is shade's result bit for bit).
    const typename Shader<T>::LightSums& sums = parts->sums;
    auto changeWith = [&](const V& moved) {
      return double(largestChannelDifference(models::saturate(shader.shadeWith(sums, moved)), c));
    };
    const T du = T(kUvStepTexels / colour.texture->width), dv = T(kUvStepTexels / colour.texture->height);
    for (const glm::vec<2, T> duv : {glm::vec<2, T>(du, 0), glm::vec<2, T>(-du, 0), glm::vec<2, T>(0, dv),
                                     glm::vec<2, T>(0, -dv)})
      out.uv = std::max(out.uv, changeWith(hitColour(sh, h, s.uv + duv, step)));
    if (colour.usesFootprint()) {
      const glm::dvec2 uv[3] = {m.src->uvs[tri[0]], m.src->uvs[tri[1]], m.src->uvs[tri[2]]};
      const double exact = hitLambda(sh, h, step);
      double far = 0.0;
      for (const auto& q : quadUvDerivativeChoices(sh.cam, P, uv, at.x, at.y, n))
        far = std::max(far, std::abs(colour.mips->lambda(q[0], q[1]) - exact));
      const double dl = kLodStep + far;
      for (const double sd : {dl, -dl}) out.uv = std::max(out.uv, changeWith(hitColour(sh, h, s.uv, step, sd)));
    }
  }
  // Normal: turned about two axes perpendicular to it, both ways. The
  // shading normal (flat's face normal, Phong's interpolated one) is
  // recomputed here as shadeHit forms it.
  V nrm;
  if (sh.mode == ShadingMode::Flat) {
    nrm = m.face_n[h.triangle];
  } else {
    const T b1 = T(h.b1), b2 = T(h.b2), b0 = T(1) - b1 - b2;
    nrm = b0 * m.n[tri[0]] + b1 * m.n[tri[1]] + b2 * m.n[tri[2]];
  }
  // cos and sin of +-kNormalStepRadians, once.
  static const struct Turn {
    double cos[2], sin[2];
  } kTurn{{std::cos(kNormalStepRadians), std::cos(-kNormalStepRadians)},
          {std::sin(kNormalStepRadians), std::sin(-kNormalStepRadians)}};
  if (glm::dot(nrm, nrm) > T(0)) {
    for (const V& axis : turnAxes(nrm))
      for (int k = 0; k < 2; ++k) {
        const T turn_cos = T(kTurn.cos[k]), turn_sin = T(kTurn.sin[k]);
        out.normal = std::max(out.normal, changeAt(turn_cos * s.nrm + turn_sin * glm::cross(axis, s.nrm), C));
      }
  }
  return out;
}

// The distinct triangles a pixel's samples hit, for the edge-fraction pass
// (edgeFractionPass): the first kPixelTriangles; a pixel whose samples hit
// more keeps those, so a sample may be counted as not near an edge it is
// near (a possible false failure of a comparison, never a false pass).
inline constexpr int kPixelTriangles = 4;
struct PixelTriangles {
  std::array<uint32_t, kPixelTriangles> mesh{}, triangle{};
  int count = 0;
  void add(uint32_t m, uint32_t t) {
    for (int k = 0; k < count; ++k)
      if (mesh[size_t(k)] == m && triangle[size_t(k)] == t) return;
    if (count < kPixelTriangles) mesh[size_t(count)] = m, triangle[size_t(count)] = t, ++count;
  }
};

// One pixel's running sums over its samples.
template <class T> struct PixelSums {
  glm::vec<3, T> final_sum{0}, raw_sum{0}, albedo{0};
  glm::vec<3, T> flipped_sum{0};  // final_sum with the backfacing samples shaded with -N
  int hits = 0, backfacing = 0;
  double nearest = 0.0, incidence = 1.0, texel_edge = kFarFromTexelEdge, triangle_edge = kFarFromTriangleEdge;
  double position = 0.0, uv = 0.0, normal = 0.0;  // sums of the samples' probes
  PixelTriangles triangles;
};

// A pixel's value from its n x n samples, box-filtered:
//   colour = sum saturate(c) / n^2,  alpha = hits / n^2;
// with diagnostics also raw = sum c / n^2, depth = the nearest hit's t,
// backfacing = the fraction of hits whose shading normal faces away,
// incidence = the smallest |cos| between a ray and its triangle's plane,
// albedo = the first hit's texture colour (0 where nothing is hit),
// texel_edge = the smallest texelEdge over the hits (texture/texel_edge.h),
// triangle_edge = the smallest distance in pixels of a hit from an edge of
// its triangle (camera/triangle_edge.h): a pixel is near an edge when any
// of its samples is; the precision probes (render/precision_probe.h):
// precision_* = sum of the samples' probes / n^2, backfacing_flip = the
// largest channel of |sum saturate(c with -N where backfacing) - sum
// saturate(c)| / n^2; the pixel's triangles into `triangles` for the
// edge-fraction pass.
template <class T> struct Accumulation {
  const Shading<T>& sh;
  Image& img;
  bool diag;  // diagnostics asked for and the image has their channels
  T inv;      // 1 / n^2
  double step;  // 1 / n: the sample grid's spacing in pixels (hitColour)
  const CameraRays& cam;  // the frame's camera (triangle_edge)
  std::vector<PixelTriangles>* triangles = nullptr;  // per pixel, with diagnostics
  int n = 1;  // samples per pixel side (the probes' 2x2 quads of samples)
  bool probes = true;  // with diag: the precision probes (RenderOptions::precision_probes)

  // Adds one sample's hit (dir: its ray direction, at: its image point,
  // both read with diagnostics).
  void add(const Hit& h, const glm::dvec3& dir, glm::dvec2 at, PixelSums<T>& px) const {
    if (px.hits == 0 || h.t < px.nearest) px.nearest = h.t;
    if (diag) {
      px.triangles.add(h.mesh, h.triangle);
      const ShadedMesh<T>& m = sh.meshes[h.mesh];
      const auto& tri = m.src->triangles[h.triangle];
      px.incidence = std::min(px.incidence, geometricIncidence(*m.src, tri, dir));
      const glm::vec<2, T> uv = interpolateUv(m.uv, tri, T(h.b1), T(h.b2));
      if (px.hits == 0) px.albedo = hitColour(sh, h, uv, step);
      const glm::vec<2, T> corners[3] = {m.uv[tri[0]], m.uv[tri[1]], m.uv[tri[2]]};
      px.texel_edge = std::min(px.texel_edge, sh.colours[m.object].texelEdge(uv, corners));
      const glm::dvec3 P[3] = {m.src->positions[tri[0]], m.src->positions[tri[1]], m.src->positions[tri[2]]};
      px.triangle_edge = std::min(px.triangle_edge, triangleEdgePixels(cam, P, h.b1, h.b2));
    }
    bool back = false;
    // With the probes the hit is shaded in parts (the same colour), which
    // its probes reuse.
    thread_local std::vector<LightSample<T>> lights;
    const bool in_parts = diag && probes && sh.mode != ShadingMode::Gouraud;
    HitParts<T> parts;
    if (in_parts) parts = shadeHitParts(sh, h, step, lights), back = parts.backfacing;
    const glm::vec<3, T> c = in_parts ? parts.c : shadeHit(sh, h, step, back);
    px.backfacing += back;
    px.final_sum += models::saturate(c);
    if (diag) {
      px.raw_sum += c;
      if (probes) {
        const SampleProbes<T> p = probeSample(sh, h, step, models::saturate(c), back, at, n,
                                                    in_parts ? &parts : nullptr, lights);
        px.position += p.position, px.uv += p.uv, px.normal += p.normal;
        px.flipped_sum += back ? p.flipped : models::saturate(c);
      }
    }
    ++px.hits;
  }

  // Writes pixel (i, j) from its sums.
  void store(const PixelSums<T>& s, int i, int j) const {
    float* px = img.pixel(i, j);
    for (int q = 0; q < 3; ++q) px[q] = float(s.final_sum[q] * inv);
    px[3] = float(T(s.hits) * inv);
    if (diag) {
      const size_t at = size_t(j) * img.width + i;
      for (int q = 0; q < 3; ++q) img.raw[at * 3 + q] = float(s.raw_sum[q] * inv);
      img.depth[at] = float(s.nearest);
      img.backfacing[at] = s.hits ? float(s.backfacing) / float(s.hits) : 0.0f;
      img.incidence[at] = s.hits ? float(s.incidence) : 0.0f;
      for (int q = 0; q < 3; ++q) img.albedo[at * 3 + q] = float(s.albedo[q]);
      img.texel_edge[at] = float(s.texel_edge);
      img.triangle_edge[at] = float(s.triangle_edge);
      img.precision_position[at] = float(s.position * double(inv));
      img.precision_uv[at] = float(s.uv * double(inv));
      img.precision_normal[at] = float(s.normal * double(inv));
      img.backfacing_flip[at] = s.backfacing && probes ? float(largestChannelDifference(s.flipped_sum, s.final_sum) * inv) : 0.0f;
      (*triangles)[at] = s.triangles;
    }
  }

  // One sample per pixel, no diagnostics: saturate(c) straight into the
  // pixel, alpha 1 (store's value with n = 1); no hit: all 0.
  void storeOne(const Hit& h, float* px) const {
    if (!h.hit) {
      px[0] = px[1] = px[2] = px[3] = 0.0f;
      return;
    }
    bool back;
    const glm::vec<3, T> c = models::saturate(shadeHit(sh, h, step, back));
    px[0] = float(c.x), px[1] = float(c.y), px[2] = float(c.z), px[3] = 1.0f;
  }
};

// The SIMD kernel's per-thread inputs and outputs: a band's hits on one
// mesh, compacted, padded to kBatchPad.
struct BatchBuffers {
  std::vector<std::uint32_t> at, tri;
  std::vector<float> b1, b2, r, g, b;
  static constexpr size_t kPad = std::max(kBatchPad, kCompactPad);
  explicit BatchBuffers(size_t n)
      : at(n + kPad), tri(n + kPad), b1(n + kPad), b2(n + kPad), r(n + kBatchPad),
        g(n + kBatchPad), b(n + kBatchPad) {}
};

// Shades the hit samples [0, count) of a band with the kernel, one mesh at
// a time, and hands each hit's saturated colour to emit(sample index, r, g,
// b): the same numbers as saturate(shadeHit) in float (shading/
// batch_shader.h).
template <class Emit>
void shadeBatched(const BatchShading& kernel, const std::vector<BatchMesh>& meshes,
                  const Rasteriser::BandHits& hits, size_t count, BatchBuffers& bb, Emit&& emit) {
  for (size_t mi = 0; mi < meshes.size(); ++mi) {
    // b1, b2 as float: as the scalar path's T(h.b1).
    const size_t c = compactBandHits(hits, count, std::uint32_t(mi), bb.at.data(), bb.tri.data(), bb.b1.data(),
                                     bb.b2.data());
    if (c == 0) continue;
    for (size_t k = c; k < (c + kBatchPad - 1) / kBatchPad * kBatchPad; ++k)
      bb.tri[k] = 0, bb.b1[k] = bb.b2[k] = 0.0f;  // padding: a valid triangle
    shadeBatch(kernel, meshes[mi], c, bb.tri.data(), bb.b1.data(), bb.b2.data(), bb.r.data(), bb.g.data(),
               bb.b.data());
    for (size_t k = 0; k < c; ++k) emit(bb.at[k], bb.r[k], bb.g[k], bb.b[k]);
  }
}

// Progress lines on stderr while a frame renders: at most once a second,
// from whichever thread gets there; "~s left" assumes a constant rate.
class Progress {
 public:
  explicit Progress(bool on) : on_(on), start_(Clock::now()), last_(start_) {}
  Clock::time_point start() const { return start_; }
  void report(int done, int total) {
    if (!on_ || !lock_.try_lock()) return;
    if (secondsSince(last_) >= 1.0 && done < total) {
      last_ = Clock::now();
      const double f = double(done) / total, el = secondsSince(start_);
      std::fprintf(stderr, "  render: %5.1f%%  %.1f s elapsed, ~%.1f s left\n", 100.0 * f, el, el * (1.0 - f) / f);
    }
    lock_.unlock();
  }

 private:
  bool on_;
  Clock::time_point start_, last_;
  std::mutex lock_;
};

// ---- Visibility: which triangle each sample's ray hits first ----------------

// The tile's samples, traced as Embree packets. A tile is kTile x kTile
// pixels of n x n samples each, side = kTile n samples along a side, the
// sample (gx, gy) of the tile's grid at pixel (x0 + gx / n, y0 + gy / n),
// offset ((gx % n + 0.5) / n, (gy % n + 0.5) / n). Packets are 4 x 4
// neighbouring samples (one pixel's 16 at 16 spp, 4 x 4 pixels at 1 spp):
// the closer the rays, the less of the BVH a packet visits. Writes
// hit[gy side + gx] (and dir[...] when dir is not empty) for every sample
// inside the image; the others are left as they were.
struct TileTracer {
  const Accel& accel;
  const CameraRays& cam;
  int n, W, H;
  const std::vector<double>& screen_x;  // per pixel column i and sample sx: cam.screenX(i + (sx + 0.5) / n)
  const std::vector<double>& screen_y;  // per pixel row j and sample sy

  void trace(int x0, int y0, std::vector<Hit>& hit, std::vector<glm::dvec3>& dir) const {
    constexpr int P = Accel::kPacketSide;
    const int side = kTile * n;
    std::array<glm::dvec3, P * P> dirs;
    std::array<bool, P * P> valid;
    std::array<Hit, P * P> hits;
    for (int by = 0; by < side; by += P)
      for (int bx = 0; bx < side; bx += P) {
        bool any = false;
        for (int r = 0; r < P * P; ++r) {
          const int gx = bx + r % P, gy = by + r / P;  // sample in the tile's grid
          const int i = x0 + gx / n, j = y0 + gy / n;
          valid[r] = i < W && j < H;
          any |= valid[r];
          if (valid[r])
            dirs[r] = cam.directionFromScreen(screen_x[size_t(i) * n + gx % n], screen_y[size_t(j) * n + gy % n]);
        }
        if (!any) continue;
        accel.intersectPacket(cam.origin, dirs.data(), valid.data(), hits.data());
        for (int r = 0; r < P * P; ++r) {
          if (!valid[r]) continue;
          const size_t at = size_t(by + r / P) * side + bx + r % P;
          hit[at] = hits[r];
          if (!dir.empty()) dir[at] = dirs[r];
        }
      }
  }
};

// ---- The two paths' units of work: visibility, then accumulation ----------

// Adds every in-image pixel of the tile at (x0, y0) from its samples'
// hits (TileTracer's layout), in the (sy, sx) order, and stores it.
template <class T>
void accumulateTile(const Accumulation<T>& acc, int n, int x0, int y0, const std::vector<Hit>& hit,
                    const std::vector<glm::dvec3>& dir) {
  const int side = kTile * n;
  for (int ty = 0; ty < kTile && y0 + ty < acc.img.height; ++ty)
    for (int tx = 0; tx < kTile && x0 + tx < acc.img.width; ++tx) {
      PixelSums<T> px;
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx) {
          const size_t at = size_t(ty * n + sy) * side + tx * n + sx;
          if (hit[at].hit)
            acc.add(hit[at], acc.diag ? dir[at] : glm::dvec3(0),
                    glm::dvec2(x0 + tx + (sx + 0.5) / n, y0 + ty + (sy + 0.5) / n), px);
        }
      acc.store(px, x0 + tx, y0 + ty);
    }
}

// The rasterised path's work on one band of kBand rows (float only):
// raster.visibility gives the first hit of every pixel's sample at one
// offset (ox, oy) inside the pixel; the accumulation turns them into
// pixels.
struct RasterBand {
  const Rasteriser& raster;
  const Accumulation<float>& acc;
  const BatchShading* kernel;  // the SIMD kernel (no diagnostics), or null: shadeHit
  const std::vector<BatchMesh>& batch_meshes;
  const CameraRays& cam;
  int n;  // samples per pixel side

  struct Buffers {  // per thread
    std::vector<Hit> hits;           // without the kernel
    Rasteriser::BandHits band_hits;  // with it
    std::vector<PixelSums<float>> sums;
    BatchBuffers bb;
    // sums: only for samples() (oneSample writes the pixels directly; its
    // frame would otherwise spend about a tenth of its time filling them).
    Buffers(int W, bool kernel, bool sums)
        : hits(kernel ? 0 : size_t(kBand) * W), sums(sums ? size_t(kBand) * W : 0),
          bb(kernel ? size_t(kBand) * W : 0) {}
  };

  // Band b's pixels.
  bool oneSamplePerPixel() const { return n == 1 && !acc.diag; }
  void render(int b, Buffers& buf) const {
    const int row0 = b * kBand, rows = std::min(kBand, acc.img.height - row0);
    if (oneSamplePerPixel())
      oneSample(b, row0, rows, buf);
    else
      samples(b, row0, rows, buf);
  }

  // One sample at the pixel centre, no diagnostics: straight to the pixels.
  void oneSample(int b, int row0, int rows, Buffers& buf) const {
    float* band = acc.img.pixel(0, row0);
    const size_t count = size_t(rows) * acc.img.width;
    if (!kernel) {
      raster.visibility(b, 0.5, 0.5, false, buf.hits);
      for (size_t k = 0; k < count; ++k) acc.storeOne(buf.hits[k], band + k * 4);
      return;
    }
    raster.visibility(b, 0.5, 0.5, false, buf.band_hits);
    std::fill(band, band + count * 4, 0.0f);
    shadeBatched(*kernel, batch_meshes, buf.band_hits, count, buf.bb, [&](std::uint32_t at, float r, float g, float bl) {
      float* px = band + size_t(at) * 4;
      px[0] = r, px[1] = g, px[2] = bl, px[3] = 1.0f;
    });
  }

  // n x n samples (or diagnostics): each pixel's sums, added in the
  // (sy, sx) order, then stored.
  void samples(int b, int row0, int rows, Buffers& buf) const {
    const int W = acc.img.width;
    std::fill(buf.sums.begin(), buf.sums.begin() + size_t(rows) * W, PixelSums<float>{});
    for (int sy = 0; sy < n; ++sy)
      for (int sx = 0; sx < n; ++sx) {
        const double ox = (sx + 0.5) / n, oy = (sy + 0.5) / n;
        if (kernel) {  // no diagnostics: add()'s final_sum += saturate(c) and ++hits
          raster.visibility(b, ox, oy, false, buf.band_hits);
          shadeBatched(*kernel, batch_meshes, buf.band_hits, size_t(rows) * W, buf.bb,
                       [&](std::uint32_t at, float r, float g, float bl) {
                         buf.sums[at].final_sum += glm::vec3(r, g, bl);
                         ++buf.sums[at].hits;
                       });
          continue;
        }
        raster.visibility(b, ox, oy, acc.diag, buf.hits);
        for (int r = 0; r < rows; ++r)
          for (int i = 0; i < W; ++i) {
            const Hit& h = buf.hits[size_t(r) * W + i];
            if (!h.hit) continue;
            const glm::dvec3 dir = acc.diag ? cam.direction(i + ox, row0 + r + oy) : glm::dvec3(0);
            acc.add(h, dir, glm::dvec2(i + ox, row0 + r + oy), buf.sums[size_t(r) * W + i]);
          }
      }
    for (int r = 0; r < rows; ++r)
      for (int i = 0; i < W; ++i) acc.store(buf.sums[size_t(r) * W + i], i, row0 + r);
  }
};

// Image::edge_fraction of every pixel, after the frame's samples are all
// in: the fraction of its n x n samples whose image-plane point lies within
// kTriangleEdgePixels of the projected boundary of a triangle hit by a
// sample of the pixel or of its 8 neighbours (triangles: each pixel's, from
// the accumulation; render/precision_probe.h). A triangle whose projection
// misses the pixel's square grown by kTriangleEdgePixels is skipped (no
// point of the pixel can be near its boundary). Rows are shared among
// `threads` threads.
// The triangles whose projection comes within kTriangleEdgePixels of a
// pixel the frame does not cover whole (alpha < 1: a silhouette, a crack, a
// sliver between hits), per such pixel: found by binning every projected
// triangle's bounding box over those pixels, so a thin triangle at a
// silhouette that no sample around hits (near a sphere's pole, along a
// knot's fold) is still a candidate there, though a rasteriser may give it
// the pixel. Triangles with a corner not in front of the camera are left to
// the 3x3 hits (they count as near every sample there). The binning visits
// every pixel of every bounding box: beyond kBinningBudget visits per pixel
// of the frame it stops and the pass uses the 3x3 hits alone (a sample may
// then count as far from an edge it is near: a possible false failure,
// never a false pass).
inline constexpr double kBinningBudget = 64.0;
struct OpenPixelTriangles {
  std::vector<int32_t> index;                                         // per pixel: its row below, or -1
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> triangles;  // per open pixel
  bool complete = true;
};
// Every triangle of every mesh projected once per frame (projectTriangle),
// per mesh, per triangle: the binning and every pixel's candidates read
// these instead of projecting a triangle again for each pixel around it
// (the same numbers: projectTriangle is a pure function of the corners).
using ProjectedMeshes = std::vector<std::vector<ProjectedTriangle>>;
ProjectedMeshes projectAll(const std::vector<TriangleMesh>& meshes, const CameraRays& cam, int threads) {
  ProjectedMeshes out(meshes.size());
  for (size_t mi = 0; mi < meshes.size(); ++mi) out[mi].resize(meshes[mi].triangles.size());
  constexpr size_t kChunk = 4096;  // triangles per job
  std::vector<std::pair<size_t, size_t>> jobs;  // (mesh, first triangle)
  for (size_t mi = 0; mi < meshes.size(); ++mi)
    for (size_t t = 0; t < meshes[mi].triangles.size(); t += kChunk) jobs.emplace_back(mi, t);
  runJobPool(jobs.size(), threads, [&](size_t k) {
    const auto [mi, first] = jobs[k];
    const TriangleMesh& m = meshes[mi];
    for (size_t ti = first; ti < std::min(first + kChunk, m.triangles.size()); ++ti) {
      const glm::u32vec3& tri = m.triangles[ti];
      const glm::dvec3 P[3] = {m.positions[tri[0]], m.positions[tri[1]], m.positions[tri[2]]};
      out[mi][ti] = projectTriangle(cam, P);
    }
  });
  return out;
}

OpenPixelTriangles openPixelTriangles(const std::vector<TriangleMesh>& meshes, const ProjectedMeshes& projected,
                                      const CameraRays& cam, const Image& img) {
  const int W = img.width, H = img.height;
  OpenPixelTriangles out;
  out.index.assign(size_t(W) * H, -1);
  int32_t open = 0;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i)
      if (img.pixel(i, j)[3] < 1.0f) out.index[size_t(j) * W + i] = open++;
  out.triangles.resize(size_t(open));
  if (open == 0) return out;
  // projectSample is affine in the image point: p = o + (x dx, y dy).
  const glm::dvec2 o = projectSample(cam, 0.0, 0.0), d = projectSample(cam, 1.0, 1.0) - o;
  const double within = kTriangleEdgePixels, budget = kBinningBudget * double(W) * H;
  double visits = 0.0;
  for (size_t mi = 0; mi < meshes.size(); ++mi) {
    const TriangleMesh& m = meshes[mi];
    for (size_t ti = 0; ti < m.triangles.size(); ++ti) {
      const ProjectedTriangle& pt = projected[mi][ti];
      if (!pt.in_front) continue;
      // The image points whose sample could lie within `within` of it.
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      for (const glm::dvec2& c : pt.c) {
        const double x = (c.x - o.x) / d.x, y = (c.y - o.y) / d.y;
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
      const double mx = within / std::abs(d.x), my = within / std::abs(d.y);
      const int i0 = std::max(0, int(std::floor(x0 - mx))), i1 = std::min(W - 1, int(std::floor(x1 + mx)));
      const int j0 = std::max(0, int(std::floor(y0 - my))), j1 = std::min(H - 1, int(std::floor(y1 + my)));
      if (i0 > i1 || j0 > j1) continue;
      visits += double(i1 - i0 + 1) * double(j1 - j0 + 1);
      if (visits > budget) {
        out.complete = false;
        for (auto& t : out.triangles) t.clear();
        return out;
      }
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
          if (const int32_t k = out.index[size_t(j) * W + i]; k >= 0)
            out.triangles[size_t(k)].emplace_back(uint32_t(mi), uint32_t(ti));
    }
  }
  return out;
}

// A pixel's candidates are the triangles its 3x3 neighbourhood hit and,
// where it is not covered whole, those openPixelTriangles bins to it.
void edgeFractionPass(const std::vector<TriangleMesh>& meshes, const CameraRays& cam, int n,
                      const std::vector<PixelTriangles>& triangles, Image& img, int threads) {
  const int W = img.width, H = img.height;
  const double within = kTriangleEdgePixels;
  const ProjectedMeshes projected = projectAll(meshes, cam, threads);
  const OpenPixelTriangles binned = openPixelTriangles(meshes, projected, cam, img);
  // A triangle's index over all meshes, for the per-thread marks that keep
  // a pixel from testing a candidate twice.
  std::vector<uint32_t> first(meshes.size() + 1, 0);
  for (size_t mi = 0; mi < meshes.size(); ++mi) first[mi + 1] = first[mi] + uint32_t(meshes[mi].triangles.size());
  // Every sample column's and row's screen coordinate, once per frame
  // (projectScreenSample: the same points as projectSample).
  std::vector<double> screen_x(size_t(W) * n), screen_y(size_t(H) * n);
  for (int i = 0; i < W; ++i)
    for (int sx = 0; sx < n; ++sx) screen_x[size_t(i) * n + sx] = cam.screenX(i + (sx + 0.5) / n);
  for (int j = 0; j < H; ++j)
    for (int sy = 0; sy < n; ++sy) screen_y[size_t(j) * n + sy] = cam.screenY(j + (sy + 0.5) / n);
  const BoundaryNearness nearness(within);  // nearProjectedBoundary(t, p, within)
  std::atomic<int> next_row{0};
  auto worker = [&]() {
    // mark[first[mesh] + triangle]: 1 + the last pixel (j W + i) that took
    // the triangle as a candidate.
    std::vector<uint32_t> mark(first.back(), 0);
    std::vector<std::pair<uint32_t, uint32_t>> seen;
    std::vector<const ProjectedTriangle*> near;
    std::vector<glm::dvec2> samples(size_t(n) * n);
    for (int j = next_row++; j < H; j = next_row++)
      for (int i = 0; i < W; ++i) {
        const uint32_t stamp = uint32_t(size_t(j) * W + i) + 1;
        seen.clear(), near.clear();
        auto take = [&](uint32_t mi, uint32_t ti) {
          uint32_t& m = mark[first[mi] + ti];
          if (m != stamp) m = stamp, seen.emplace_back(mi, ti);
        };
        for (int y = std::max(0, j - 1); y <= std::min(H - 1, j + 1); ++y)
          for (int x = std::max(0, i - 1); x <= std::min(W - 1, i + 1); ++x) {
            const PixelTriangles& t = triangles[size_t(y) * W + x];
            for (int k = 0; k < t.count; ++k) take(t.mesh[size_t(k)], t.triangle[size_t(k)]);
          }
        if (const int32_t k = binned.index[size_t(j) * W + i]; k >= 0)
          for (const auto& [mi, ti] : binned.triangles[size_t(k)]) take(mi, ti);
        if (seen.empty()) {  // no candidate: no sample is near an edge (the background away from the objects)
          img.edge_fraction[size_t(j) * W + i] = 0.0f;
          continue;
        }
        glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (int sy = 0; sy < n; ++sy)
          for (int sx = 0; sx < n; ++sx) {
            const glm::dvec2 p =
                projectScreenSample(cam, screen_x[size_t(i) * n + sx], screen_y[size_t(j) * n + sy]);
            samples[size_t(sy) * n + sx] = p;
            lo = glm::min(lo, p), hi = glm::max(hi, p);
          }
        lo -= within, hi += within;
        for (const std::pair<uint32_t, uint32_t>& key : seen) {
          const ProjectedTriangle& pt = projected[key.first][key.second];
          if (pt.in_front && (pt.hi.x < lo.x || pt.hi.y < lo.y || pt.lo.x > hi.x || pt.lo.y > hi.y)) continue;
          near.push_back(&pt);
        }
        // Whether a sample is near some candidate does not depend on the
        // order they are tried in.
        int count = 0;
        for (const glm::dvec2& p : samples)
          for (const ProjectedTriangle* t : near)
            if (nearness(*t, p)) {
              ++count;
              break;
            }
        img.edge_fraction[size_t(j) * W + i] = float(count) / float(n * n);
      }
  };
  runOnThreads(std::min(threads, H), worker);
}

// n of the n x n sample grid (spp is a perfect square).
int samplesPerSide(const RenderOptions& opt) { return int(std::lround(std::sqrt(double(opt.spp)))); }

int threadCount(const RenderOptions& opt) {
  return opt.threads > 0 ? opt.threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace

struct PreparedScene::Impl {
  Scene scene;
  std::vector<TriangleMesh> meshes;
  std::vector<size_t> mesh_object;  // the scene object of each mesh (geometry/scene_meshes.h)
  // The default material's texture, then those of objects with their own.
  std::vector<std::unique_ptr<Texture>> textures;
  std::vector<const Texture*> object_texture;  // per object (null: untextured)
  // Mip chains of the textures a trilinear filter reads (texture/mip_chain.h).
  std::vector<std::unique_ptr<MipChain>> chains;
  std::vector<const MipChain*> object_chain;  // per object (null: none)
  std::optional<Accel> accel;
  std::vector<bool> back_faces_hidden;  // per mesh: geometry/front_faces.h, from the camera
  bool rasterisable = false;            // Rasteriser::applicable for the scene's camera (fixed)
  size_t bvh_culled = 0;                // back faces left out of the BVH
  std::variant<std::monostate, Shading<float>, Shading<double>> shading;
  // Float only: the SIMD kernel, when it covers the scene (shading/batch_shader.h).
  std::optional<BatchShading> batch;
  std::vector<BatchMesh> batch_meshes;  // with batch: each mesh's vertices interleaved
  Precision precision;
  double setup_seconds = 0.0;
  size_t triangles = 0;

  template <class T>
  void renderT(const Shading<T>& sh, const RenderOptions& opt, Image& img, RenderStats& stats) const;
  void renderRasterised(const Shading<float>& sh, const RenderOptions& opt, Image& img, RenderStats& stats,
                        Progress& progress) const;
  template <class T>
  void renderTraced(const Shading<T>& sh, const RenderOptions& opt, Image& img, RenderStats& stats,
                    Progress& progress) const;
};

PreparedScene::PreparedScene(const Scene& input, Precision precision, bool cull_back_faces)
    : impl_(new Impl) {
  // Texture source "model": one object, so one texture, per primitive
  // (geometry/model_textures.h).
  const Scene scene = resolveModelTextures(input);
  auto t0 = Clock::now();
  Impl& d = *impl_;
  // Numbers this precision cannot compute with are an error naming the field
  // (the scene's own precision was checked when it was loaded).
  checkPrecision(scene, precision);
  d.scene = scene;
  d.precision = precision;
  SceneMeshes sm = sceneMeshes(scene);
  d.meshes = std::move(sm.meshes);
  d.mesh_object = std::move(sm.object);
  for (const auto& m : d.meshes) d.triangles += m.triangles.size();
  const glm::dvec3 eye = CameraRays(scene.camera).origin;
  d.rasterisable = Rasteriser::applicable(d.meshes, CameraRays(scene.camera));
  // Not culling: the conditions are not checked (the closed-surface check
  // of a model mesh is the costly one) and no mesh counts as hidden.
  for (size_t k = 0; k < d.meshes.size(); ++k)
    d.back_faces_hidden.push_back(cull_back_faces &&
                                  objectBackFacesNeverFirstHit(scene.objects[d.mesh_object[k]], d.meshes[k], eye));
  const Texture* default_texture = nullptr;
  if (scene.material.texture) {
    d.textures.push_back(std::make_unique<Texture>(loadTexture(*scene.material.texture)));
    default_texture = d.textures.back().get();
  }
  const MipChain* default_chain = nullptr;
  auto chainOf = [&](const Material& m, const Texture* t) -> const MipChain* {
    if (!t || m.texture->filter != TextureFilter::Trilinear) return nullptr;
    d.chains.push_back(std::make_unique<MipChain>(mipChain(*t)));
    return d.chains.back().get();
  };
  if (default_texture) default_chain = chainOf(scene.material, default_texture);
  for (const SceneObject& o : scene.objects) {
    if (!o.material) {
      d.object_texture.push_back(default_texture);
      d.object_chain.push_back(default_chain);
    } else if (!o.material->texture) {
      d.object_texture.push_back(nullptr);
      d.object_chain.push_back(nullptr);
    } else {
      d.textures.push_back(std::make_unique<Texture>(loadTexture(*o.material->texture)));
      d.object_texture.push_back(d.textures.back().get());
      d.object_chain.push_back(chainOf(*o.material, d.textures.back().get()));
    }
  }
  // The ray paths' BVH: without the back faces no camera ray hits first
  // (geometry/front_faces.h, trianglesNotFacingAway and its conditions).
  std::vector<std::optional<std::vector<uint32_t>>> only(d.meshes.size());
  for (size_t k = 0; cull_back_faces && k < d.meshes.size(); ++k) {
    if (!d.back_faces_hidden[k]) continue;  // condition 1
    only[k] = trianglesNotFacingAway(d.meshes[k], eye);
    d.bvh_culled += d.meshes[k].triangles.size() - only[k]->size();
  }
  d.accel.emplace(d.meshes, precision, only);
  if (precision == Precision::Float) {
    d.shading.emplace<Shading<float>>(d.scene, d.meshes, d.mesh_object, d.object_texture, d.object_chain);
    // The kernel shades with one material: not built for objects with their own.
    if (!hasObjectMaterials(d.scene)) d.batch = batchShading(d.scene, default_texture, eye);
    if (d.batch)
      for (const auto& m : std::get<Shading<float>>(d.shading).meshes)
        d.batch_meshes.push_back(batchMesh(m.p, m.n, m.uv, m.src->triangles));
  } else
    d.shading.emplace<Shading<double>>(d.scene, d.meshes, d.mesh_object, d.object_texture, d.object_chain);
  d.setup_seconds = secondsSince(t0);
}

PreparedScene::~PreparedScene() = default;
Precision PreparedScene::precision() const { return impl_->precision; }
double PreparedScene::setupSeconds() const { return impl_->setup_seconds; }
size_t PreparedScene::triangleCount() const { return impl_->triangles; }
const std::vector<TriangleMesh>& PreparedScene::meshes() const { return impl_->meshes; }

void PreparedScene::render(const RenderOptions& opt, Image& img, RenderStats* stats_out) const {
  const Camera& c = impl_->scene.camera;
  if (img.width != c.width || img.height != c.height || img.rgba.size() != size_t(c.width) * c.height * 4)
    throw std::invalid_argument("PreparedScene::render: the image is " + std::to_string(img.width) + "x" +
                                std::to_string(img.height) + ", the camera " + std::to_string(c.width) +
                                "x" + std::to_string(c.height));
  if (opt.precision != impl_->precision)
    throw std::invalid_argument(std::string("PreparedScene::render: prepared for ") +
                                toString(impl_->precision) + ", asked for " + toString(opt.precision));
  RenderStats stats;
  if (auto* f = std::get_if<Shading<float>>(&impl_->shading))
    impl_->renderT(*f, opt, img, stats);
  else
    impl_->renderT(std::get<Shading<double>>(impl_->shading), opt, img, stats);
  if (stats_out) *stats_out = stats;
}

PreparedScene::ProbeCheck PreparedScene::checkProbe(double x, double y, int spp) const {
  const Impl& d = *impl_;
  const CameraRays cam(d.scene.camera);
  const Hit h = d.accel->intersect(cam.origin, cam.direction(x, y));
  ProbeCheck out;
  if (!h.hit) return out;
  out.hit = true;
  const double step = 1.0 / std::lround(std::sqrt(double(spp)));
  auto both = [&](const auto& sh) {
    using Nudge = ShadingNudge<typename std::decay_t<decltype(sh)>::V::value_type>;
    bool back = false;
    const Nudge none;
    out.colour = glm::dvec3(models::saturate(shadeHit(sh, h, step, back)));
    out.unperturbed = glm::dvec3(models::saturate(shadeHit(sh, h, step, back, &none)));
  };
  if (auto* f = std::get_if<Shading<float>>(&d.shading))
    both(*f);
  else
    both(std::get<Shading<double>>(d.shading));
  return out;
}

// One frame: visibility (rasterised when the float path may, else traced)
// and accumulation, on threadCount(opt) threads; the timings into stats.
template <class T>
void PreparedScene::Impl::renderT(const Shading<T>& sh, const RenderOptions& opt, Image& img,
                                  RenderStats& stats) const {
  Progress progress(opt.progress);
  if constexpr (std::is_same_v<T, float>) {
    if (opt.rasterise && rasterisable)
      renderRasterised(sh, opt, img, stats, progress);
    else
      renderTraced(sh, opt, img, stats, progress);
  } else {
    renderTraced(sh, opt, img, stats, progress);
  }
  stats.setup_seconds = setup_seconds;
  stats.trace_seconds = secondsSince(progress.start());
}

// Rasterised visibility (float, every vertex in front of the camera; back
// faces of the meshes in back_faces_hidden dropped when binning): the
// image in bands of kBand rows, handed to the threads in order.
void PreparedScene::Impl::renderRasterised(const Shading<float>& sh, const RenderOptions& opt, Image& img,
                                           RenderStats& stats, Progress& progress) const {
  const CameraRays cam(scene.camera);
  const int n = samplesPerSide(opt);
  const bool diag = opt.diagnostics && !img.raw.empty();
  std::vector<PixelTriangles> triangles(diag ? size_t(img.width) * img.height : 0);
  const Accumulation<float> acc{sh, img, diag, 1.0f / float(n * n), 1.0 / n, cam, &triangles, n,
                                opt.precision_probes};
  stats.visibility = "rasterised";
  const Rasteriser raster(meshes, cam, kBand, opt.cull_back_faces ? back_faces_hidden : std::vector<bool>{},
                          threadCount(opt));
  stats.culled_triangles = raster.culledTriangles();
  const BatchShading* kernel = batch && opt.batch_shading && !acc.diag ? &*batch : nullptr;
  if (kernel) stats.shading = std::string("SIMD, ") + batchShaderTarget();
  const RasterBand band{raster, acc, kernel, batch_meshes, cam, n};
  std::atomic<int> next_band{0}, bands_done{0};
  auto worker = [&]() {
    RasterBand::Buffers buf(img.width, kernel != nullptr, !band.oneSamplePerPixel());
    for (int b = next_band++; b < raster.bands(); b = next_band++) {
      band.render(b, buf);
      progress.report(++bands_done, raster.bands());
    }
  };
  runOnThreads(std::min(threadCount(opt), raster.bands()), worker);
  if (diag && opt.precision_probes) {
    const auto t0 = Clock::now();
    edgeFractionPass(meshes, cam, n, triangles, img, threadCount(opt));
    stats.edge_fraction_seconds = secondsSince(t0);
  }
}

// Traced visibility (Embree packets; the BVH without the back faces no
// camera ray hits first, geometry/front_faces.h): the image in tiles of
// kTile x kTile pixels, handed to the threads in order.
template <class T>
void PreparedScene::Impl::renderTraced(const Shading<T>& sh, const RenderOptions& opt, Image& img,
                                       RenderStats& stats, Progress& progress) const {
  const CameraRays cam(scene.camera);
  const int n = samplesPerSide(opt), W = img.width, H = img.height;
  const bool diag = opt.diagnostics && !img.raw.empty();
  std::vector<PixelTriangles> triangles(diag ? size_t(W) * H : 0);
  const Accumulation<T> acc{sh, img, diag, T(1) / T(n * n), 1.0 / n, cam, &triangles, n, opt.precision_probes};
  stats.visibility = std::is_same_v<T, float> ? "Embree 16-ray packets (float)"
                                              : "Embree 16-ray packets, double-precision watertight test";
  stats.culled_triangles = bvh_culled;
  // The screen coordinates of every sample column and row, once per frame
  // (the directions are bit-identical to cam.direction(i + ox, j + oy)).
  std::vector<double> screen_x(size_t(W) * n), screen_y(size_t(H) * n);
  for (int i = 0; i < W; ++i)
    for (int sx = 0; sx < n; ++sx) screen_x[size_t(i) * n + sx] = cam.screenX(i + (sx + 0.5) / n);
  for (int j = 0; j < H; ++j)
    for (int sy = 0; sy < n; ++sy) screen_y[size_t(j) * n + sy] = cam.screenY(j + (sy + 0.5) / n);
  const TileTracer tracer{*accel, cam, n, W, H, screen_x, screen_y};
  const int tiles_x = (W + kTile - 1) / kTile, tiles = tiles_x * ((H + kTile - 1) / kTile);
  std::atomic<int> next_tile{0}, tiles_done{0};
  auto worker = [&]() {
    std::vector<Hit> hit(size_t(kTile * n) * (kTile * n));  // TileTracer's layout
    std::vector<glm::dvec3> dir(acc.diag ? hit.size() : 0);
    for (int k = next_tile++; k < tiles; k = next_tile++) {
      const int x0 = (k % tiles_x) * kTile, y0 = (k / tiles_x) * kTile;
      tracer.trace(x0, y0, hit, dir);
      accumulateTile(acc, n, x0, y0, hit, dir);
      progress.report(++tiles_done, tiles);
    }
  };
  runOnThreads(std::min(threadCount(opt), tiles), worker);
  if (diag && opt.precision_probes) {
    const auto t0 = Clock::now();
    edgeFractionPass(meshes, cam, n, triangles, img, threadCount(opt));
    stats.edge_fraction_seconds = secondsSince(t0);
  }
}

Image renderScene(const Scene& scene, const RenderOptions& options, RenderStats* stats) {
  PreparedScene prepared(scene, options.precision, options.cull_back_faces);
  Image img(scene.camera.width, scene.camera.height, options.diagnostics);
  prepared.render(options, img, stats);
  return img;
}

}  // namespace xval
