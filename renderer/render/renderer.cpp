#include "render/renderer.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <thread>

#include "camera/camera.h"
#include "geometry/mesh.h"
#include "render/accel.h"
#include "shading/shader.h"
#include "shading/surface_colour.h"
#include "texture/texture.h"

namespace xval {

RenderOptions defaultOptions(const Scene& scene) {
  RenderOptions o;
  o.spp = scene.render.spp;
  o.precision = scene.render.precision;
  return o;
}

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A mesh's attributes converted once to the working precision T.
template <class T> struct ShadedMesh {
  using V = glm::vec<3, T>;
  const TriangleMesh* src;
  std::vector<V> p, n, face_n, vertex_colour;
  std::vector<glm::vec<2, T>> uv;
};

template <class T>
ShadedMesh<T> prepareMesh(const TriangleMesh& m, ShadingMode mode, const Shader<T>& shader,
                          const SurfaceColour<T>& colour, glm::vec<3, T> eye) {
  ShadedMesh<T> s;
  s.src = &m;
  s.p.reserve(m.positions.size());
  for (auto& v : m.positions) s.p.emplace_back(v);
  for (auto& v : m.normals) s.n.emplace_back(v);
  for (auto& v : m.uvs) s.uv.emplace_back(v);
  if (mode == ShadingMode::Flat) {
    s.face_n.reserve(m.triangles.size());
    for (const auto& t : m.triangles) {
      glm::dvec3 g = glm::cross(m.positions[t[1]] - m.positions[t[0]],
                                m.positions[t[2]] - m.positions[t[0]]);
      double len = glm::length(g);
      g = len > 0.0 ? g / len : glm::dvec3(0.0);
      if (glm::dot(g, m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]]) < 0.0) g = -g;
      s.face_n.emplace_back(g);
    }
  }
  if (mode == ShadingMode::Gouraud) s.vertex_colour = gouraudVertexColours(shader, m, colour, eye);
  return s;
}

// |cos| between a ray and the hit triangle's plane normal.
double geometricIncidence(const TriangleMesh& m, const glm::u32vec3& t, glm::dvec3 dir) {
  glm::dvec3 g = glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
  double len = glm::length(g);
  return len > 0.0 ? std::abs(glm::dot(g / len, dir)) : 0.0;
}

template <class T>
void renderT(const Scene& scene, const std::vector<TriangleMesh>& meshes, const Texture* texture,
             const Accel& accel, const RenderOptions& opt, Image& img, RenderStats& stats) {
  using V = glm::vec<3, T>;
  auto t0 = Clock::now();
  const Shader<T> shader(scene.material, scene.lights);
  const SurfaceColour<T> colour(scene.material, texture);
  const CameraRays cam(scene.camera);
  const V eye(cam.origin);
  std::vector<ShadedMesh<T>> shaded;
  for (const auto& m : meshes) shaded.push_back(prepareMesh<T>(m, scene.shading, shader, colour, eye));
  stats.setup_seconds += secondsSince(t0);

  const int n = int(std::lround(std::sqrt(double(opt.spp))));
  const int W = img.width, H = img.height;
  const bool want_raw = !img.raw.empty();
  std::atomic<int> next_row{0}, rows_done{0};
  auto t_trace = Clock::now();
  std::mutex progress_lock;
  auto last_report = t_trace;

  auto worker = [&]() {
    for (int j = next_row++; j < H; j = next_row++) {
      for (int i = 0; i < W; ++i) {
        V sum_final(0), sum_raw(0);
        int hits = 0, backfacing = 0;
        double nearest = 0.0, incidence = 1.0;
        V albedo(0);
        for (int sy = 0; sy < n; ++sy) {
          for (int sx = 0; sx < n; ++sx) {
            double x = i + (sx + 0.5) / n, y = j + (sy + 0.5) / n;
            glm::dvec3 dir = cam.direction(x, y);
            Hit h = accel.intersect(cam.origin, dir);
            if (!h.hit) continue;
            if (hits == 0 || h.t < nearest) nearest = h.t;
            const ShadedMesh<T>& m = shaded[h.mesh];
            const auto& tri = m.src->triangles[h.triangle];
            if (want_raw) incidence = std::min(incidence, geometricIncidence(*m.src, tri, dir));
            const T b1 = T(h.b1), b2 = T(h.b2), b0 = T(1) - b1 - b2;
            V c;
            if (want_raw && hits == 0) {
              glm::vec<2, T> uv = b0 * m.uv[tri[0]] + b1 * m.uv[tri[1]] + b2 * m.uv[tri[2]];
              albedo = colour.at(uv);
            }
            if (scene.shading == ShadingMode::Gouraud) {
              c = b0 * m.vertex_colour[tri[0]] + b1 * m.vertex_colour[tri[1]] +
                  b2 * m.vertex_colour[tri[2]];
            } else {
              V p = b0 * m.p[tri[0]] + b1 * m.p[tri[1]] + b2 * m.p[tri[2]];
              V nrm;
              if (scene.shading == ShadingMode::Flat) {
                nrm = m.face_n[h.triangle];
              } else {
                nrm = b0 * m.n[tri[0]] + b1 * m.n[tri[1]] + b2 * m.n[tri[2]];
                T len = glm::length(nrm);
                nrm = len > T(0) ? nrm / len : V(0);  // zero-length normals stay 0
              }
              glm::vec<2, T> uv = b0 * m.uv[tri[0]] + b1 * m.uv[tri[1]] + b2 * m.uv[tri[2]];
              V v = glm::normalize(eye - p);
              backfacing += glm::dot(nrm, v) < T(0);
              c = shader.shade(p, nrm, v, colour.at(uv));
            }
            sum_final += models::saturate(c);
            sum_raw += c;
            ++hits;
          }
        }
        const T inv = T(1) / T(n * n);
        float* px = img.pixel(i, j);
        for (int k = 0; k < 3; ++k) px[k] = float(sum_final[k] * inv);
        px[3] = float(T(hits) * inv);
        if (want_raw) {
          const size_t at = size_t(j) * W + i;
          for (int k = 0; k < 3; ++k) img.raw[at * 3 + k] = float(sum_raw[k] * inv);
          img.depth[at] = float(nearest);
          img.backfacing[at] = hits ? float(backfacing) / float(hits) : 0.0f;
          img.incidence[at] = hits ? float(incidence) : 0.0f;
          for (int k = 0; k < 3; ++k) img.albedo[at * 3 + k] = float(albedo[k]);
        }
      }
      int done = ++rows_done;
      // Progress, at most once a second, from whichever thread gets there.
      if (opt.progress && progress_lock.try_lock()) {
        if (secondsSince(last_report) >= 1.0 && done < H) {
          last_report = Clock::now();
          double f = double(done) / H, el = secondsSince(t_trace);
          std::fprintf(stderr, "  render: %5.1f%%  %.1f s elapsed, ~%.1f s left\n", 100.0 * f,
                       el, el * (1.0 - f) / f);
        }
        progress_lock.unlock();
      }
    }
  };

  int threads = opt.threads > 0 ? opt.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  stats.trace_seconds += secondsSince(t_trace);
}

}  // namespace

Image renderScene(const Scene& scene, const RenderOptions& options, RenderStats* stats_out) {
  RenderStats stats;
  auto t0 = Clock::now();
  std::vector<TriangleMesh> meshes;
  for (const Shape& s : scene.objects) meshes.push_back(tessellate(s));
  std::optional<Texture> texture;
  if (scene.material.texture) texture = loadTexture(*scene.material.texture);
  Accel accel(meshes, options.precision);
  stats.setup_seconds = secondsSince(t0);

  Image img(scene.camera.width, scene.camera.height, true);
  const Texture* tex = texture ? &*texture : nullptr;
  if (options.precision == Precision::Float)
    renderT<float>(scene, meshes, tex, accel, options, img, stats);
  else
    renderT<double>(scene, meshes, tex, accel, options, img, stats);
  if (stats_out) *stats_out = stats;
  return img;
}

}  // namespace xval
