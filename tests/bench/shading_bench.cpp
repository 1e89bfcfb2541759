// Google Benchmark for the shading kernels: classic Phong against the YIQ
// luma model (the "YIQ costs <= 2% more than Phong" is about the
// whole frame; this isolates the model), the reduced YIQ formula against
// the listing's two matrix products, and the bilinear texture lookup.
// Inputs: 4096 surface samples drawn once from a fixed seed (unit normals,
// eye and light above the surface, colours in [0,1]); one light and an
// ambient term, as in the paper's Table 2 scenes.
//
//   build/tests/bench/xval_shading_bench [--benchmark_repetitions=5]
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "geometry/mesh.h"
#include "shading/batch_shader.h"
#include "shading/models.h"
#include "shading/shader.h"
#include "texture/brick.h"
#include "texture/texture.h"
#include "support/random_hits.h"

namespace {

using namespace xval;

template <class T> struct Samples {
  using V = glm::vec<3, T>;
  std::vector<V> p, n, v, c;
  std::vector<glm::vec<2, T>> uv;
  explicit Samples(size_t count) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> u(-1.0, 1.0), u01(0.0, 1.0);
    for (size_t k = 0; k < count; ++k) {
      glm::dvec3 nn = glm::normalize(glm::dvec3(u(rng), u(rng), 1.0 + u01(rng)));
      p.emplace_back(V(u(rng), u(rng), u(rng)));
      n.emplace_back(V(nn));
      v.emplace_back(V(glm::normalize(glm::dvec3(u(rng), u(rng), 2.0))));
      c.emplace_back(V(u01(rng), u01(rng), u01(rng)));
      uv.emplace_back(glm::vec<2, T>(T(12 * u01(rng)), T(2 * u01(rng))));
    }
  }
};

Material material(bool yiq) {
  Material m;
  if (yiq) {
    YiqLuma y;
    y.shininess = 55;
    m.model = y;
  } else {
    ClassicPhong c;
    c.shininess = 55;
    m.model = c;
  }
  return m;
}

std::vector<Light> lights() {
  return {PointLight{{-0.5, 2.0, 1.25}, glm::dvec3(1.0), {}}, AmbientLight{glm::dvec3(0.1)}};
}

template <class T> void shade(benchmark::State& state, bool yiq) {
  const Samples<T> s(4096);
  const Shader<T> shader(material(yiq), lights());
  for (auto _ : state) {
    glm::vec<3, T> acc(0);
    for (size_t k = 0; k < s.p.size(); ++k) acc += shader.shade(s.p[k], s.n[k], s.v[k], s.c[k]);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(s.p.size()));
}

void BM_ShadeClassicPhongFloat(benchmark::State& st) { shade<float>(st, false); }
void BM_ShadeYiqLumaFloat(benchmark::State& st) { shade<float>(st, true); }
void BM_ShadeClassicPhongDouble(benchmark::State& st) { shade<double>(st, false); }
void BM_ShadeYiqLumaDouble(benchmark::State& st) { shade<double>(st, true); }
BENCHMARK(BM_ShadeClassicPhongFloat);
BENCHMARK(BM_ShadeYiqLumaFloat);
BENCHMARK(BM_ShadeClassicPhongDouble);
BENCHMARK(BM_ShadeYiqLumaDouble);

// The YIQ step alone: the listing (RGB->YIQ, scale Y, YIQ->RGB) against the
// reduced F = C + (Y (Dl - 1) + S - off)(1,1,1) (shading/models.h).
template <bool kListing> void BM_YiqStep(benchmark::State& state) {
  const Samples<float> s(4096);
  for (auto _ : state) {
    glm::vec3 acc(0);
    for (size_t k = 0; k < s.c.size(); ++k) {
      const float dl = s.v[k].z, spec = s.n[k].x;
      acc += kListing ? models::yiqLumaListing(s.c[k], dl, spec, 0.1f)
                      : models::yiqLuma(s.c[k], dl, spec, 0.1f);
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * 4096);
}
BENCHMARK(BM_YiqStep<true>)->Name("BM_YiqStepListing");
BENCHMARK(BM_YiqStep<false>)->Name("BM_YiqStepReduced");

// Bilinear lookup of the 512 x 512 brick texture at scattered uv.
template <class T> void BM_TextureBilinear(benchmark::State& state) {
  const Samples<T> s(4096);
  const Texture tex = makeBrickTexture();
  for (auto _ : state) {
    glm::vec<3, T> acc(0);
    for (const auto& uv : s.uv) acc += tex.lookup(uv, TextureFilter::Bilinear);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * 4096);
}
BENCHMARK(BM_TextureBilinear<float>)->Name("BM_TextureBilinearFloat");

// The fast path's SIMD kernel: 4096 hits at random points of random
// triangles of the paper's knot (tessellated as in Table 2), brick texture,
// bilinear, seen from the Table 2 camera.
void batchShade(benchmark::State& state, bool yiq) {
  Scene scene;
  scene.objects = {TorusKnot{}};
  scene.material = material(yiq);
  scene.material.texture = TextureSpec{};
  scene.lights = lights();
  const glm::dvec3 eye = scene.camera.position;
  const TriangleMesh mesh = tessellate(scene.objects[0].shape);
  std::vector<glm::vec3> p, n;
  std::vector<glm::vec2> uv;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    p.emplace_back(mesh.positions[i] - eye);
    n.emplace_back(mesh.normals[i]);
    uv.emplace_back(mesh.uvs[i]);
  }
  const BatchMesh bm = batchMesh(p, n, uv, mesh.triangles);
  const Texture tex = loadTexture(*scene.material.texture);
  const auto shading = batchShading(scene, &tex, eye);
  constexpr size_t kCount = 4096;
  const test::RandomHits hits = test::randomHits(mesh.triangles.size(), kCount, 12345);
  std::vector<float> r(kCount), g(kCount), b(kCount);
  for (auto _ : state) {
    shadeBatch(*shading, bm, kCount, hits.tri.data(), hits.b1.data(), hits.b2.data(), r.data(), g.data(),
               b.data());
    benchmark::DoNotOptimize(r.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(kCount));
  state.SetLabel(batchShaderTarget());
}
void BM_BatchShadeClassicPhong(benchmark::State& st) { batchShade(st, false); }
void BM_BatchShadeYiqLuma(benchmark::State& st) { batchShade(st, true); }
BENCHMARK(BM_BatchShadeClassicPhong);
BENCHMARK(BM_BatchShadeYiqLuma);

}  // namespace

BENCHMARK_MAIN();
