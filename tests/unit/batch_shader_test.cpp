// The SIMD shading kernel (shading/batch_shader.h) gives bit-identical
// pixels to shading one hit at a time, on every pixel, for every case it
// covers; and it declines the cases it does not cover.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <hwy/targets.h>

#include "geometry/mesh.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"
#include "shading/batch_shader.h"
#include "texture/texture.h"
#include "support/random_hits.h"

using namespace xval;

namespace {

// Renders the scene on the fast path with and without the kernel; every
// value of every pixel must be equal.
void expectBitIdentical(const Scene& s, int spp = 1) {
  RenderOptions simd, scalar;
  simd.spp = scalar.spp = spp;
  simd.precision = scalar.precision = Precision::Float;
  simd.diagnostics = scalar.diagnostics = false;  // the kernel's case
  scalar.batch_shading = false;
  RenderStats ss, sc;
  const Image a = renderScene(s, simd, &ss), b = renderScene(s, scalar, &sc);
  EXPECT_EQ(ss.shading.rfind("SIMD", 0), 0u) << ss.shading;
  EXPECT_EQ(sc.shading, "one hit at a time");
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  size_t differ = 0, covered = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) differ += std::memcmp(&a.rgba[i], &b.rgba[i], sizeof(float)) != 0;
  for (size_t i = 0; i < a.rgba.size() / 4; ++i) covered += a.rgba[i * 4 + 3] > 0;
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(covered, a.rgba.size() / 4 / 20);  // the object is in view
}

Scene sphereScene() {
  Scene s;
  s.camera.width = s.camera.height = 96;
  UvSphere sphere;
  sphere.radius = 1.5;
  s.objects = {sphere};
  return s;
}

}  // namespace

TEST(BatchShader, Table2KnotYiqIsBitIdentical) {
  expectBitIdentical(loadScene(std::string(XVAL_REFERENCE_DIR) + "/scenes/table2_knot_yiq.json"));
}

// Several samples per pixel: the kernel's colours are summed per pixel in
// the same order as one hit at a time.
TEST(BatchShader, Table2KnotYiqAt4SppIsBitIdentical) {
  Scene s = loadScene(std::string(XVAL_REFERENCE_DIR) + "/scenes/table2_knot_yiq.json");
  s.camera.width = s.camera.height = 360;
  expectBitIdentical(s, 4);
}

TEST(BatchShader, Table2KnotClassicPhongIsBitIdentical) {
  Scene s = loadScene(std::string(XVAL_REFERENCE_DIR) + "/scenes/table2_knot_yiq.json");
  s.material.model = ClassicPhong{};
  expectBitIdentical(s);
}

// Every light kind (attenuated point, directional, spot with its cone edge
// in view), nearest texture, two lights on the classic model.
TEST(BatchShader, EveryLightKindAndNearestTextureIsBitIdentical) {
  Scene s = sphereScene();
  TextureSpec t;
  t.filter = TextureFilter::Nearest;
  s.material.texture = t;
  ClassicPhong m;
  m.ks = 0.7, m.shininess = 20;
  s.material.model = m;
  SpotLight spot;
  spot.position = {0, 0, 5}, spot.direction = {0, 0, -1}, spot.cutoff_deg = 12;
  spot.attenuation = {1.0, 0.1, 0.02};
  s.lights = {PointLight{{2, 2, 3}, {1.0, 0.8, 0.6}, {1.0, 0.2, 0.05}},
              DirectionalLight{{-1, -0.5, -1}, {0.3, 0.4, 0.5}}, spot, AmbientLight{{0.1, 0.1, 0.1}}};
  expectBitIdentical(s);
  YiqLuma y;
  y.shininess = 200;
  s.material.model = y;
  expectBitIdentical(s);
}


// Without a texture (base colour), shininess 0 (S = 1 everywhere), and a
// light so far away that |D|^2 overflows float (towardsLight's rescaling).
TEST(BatchShader, BaseColourShininessZeroAndFarLightAreBitIdentical) {
  Scene s = sphereScene();
  s.material.base_color = {0.8, 0.3, 0.2};
  YiqLuma y;
  y.shininess = 0;
  s.material.model = y;
  s.lights = {PointLight{{1e20, 1e20, 1e20}, glm::dvec3(1.0), {}}, PointLight{{1, 1, 4}, glm::dvec3(0.5), {}}};
  expectBitIdentical(s);
}

TEST(BatchShader, DeclinesWhatItDoesNotCover) {
  Scene s = sphereScene();
  const glm::dvec3 eye(0, 0, 4.2);
  EXPECT_TRUE(batchShading(s, nullptr, eye).has_value());  // the default: classic paper, phong
  s.shading = ShadingMode::Flat;
  EXPECT_FALSE(batchShading(s, nullptr, eye).has_value());
  s.shading = ShadingMode::Gouraud;
  EXPECT_FALSE(batchShading(s, nullptr, eye).has_value());
  s.shading = ShadingMode::Phong;
  ClassicPhong course;
  course.variant = ClassicPhong::Variant::Course;
  s.material.model = course;
  EXPECT_FALSE(batchShading(s, nullptr, eye).has_value());
  s.material.model = Trilight{};
  EXPECT_FALSE(batchShading(s, nullptr, eye).has_value());
  s.material.model = ClassicPhong{};
  s.material.texture = TextureSpec{TextureSpec::Source::Brick, {}, TextureFilter::Trilinear, {}};
  EXPECT_FALSE(batchShading(s, nullptr, eye).has_value());  // the level needs each hit's footprint
  s.material.texture.reset();
  s.normalize_normal = false;
  EXPECT_FALSE(batchShading(s, nullptr, eye).has_value());  // the listing's normalize(R): the scalar path
  s.normalize_normal = true;
  s.material.model = Trilight{};
  // Declined scenes render one hit at a time.
  RenderOptions o;
  o.precision = Precision::Float;
  o.diagnostics = false;
  RenderStats st;
  renderScene(s, o, &st);
  EXPECT_EQ(st.shading, "one hit at a time");
}

// Every instruction set the kernel was compiled for that this CPU runs
// (e.g. SSE4 and AVX2 here; a CI machine may pick another one by default).
TEST(BatchShader, EveryCompiledInstructionSetIsBitIdentical) {
  Scene s = loadScene(std::string(XVAL_REFERENCE_DIR) + "/scenes/table2_knot_yiq.json");
  s.camera.width = s.camera.height = 240;
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  EXPECT_GE(targets.size(), 2u);  // at least the baseline and one more
  for (int64_t t : targets) {
    hwy::SetSupportedTargetsForTest(t);
    SCOPED_TRACE(hwy::TargetName(t));
    EXPECT_STREQ(batchShaderTarget(), hwy::TargetName(t));
    expectBitIdentical(s);
  }
  hwy::SetSupportedTargetsForTest(0);  // back to what the CPU has
}

// The kernel's three ways to read a texel give the same values: packed
// codes divided by 255, packed codes through the table, and the float rgb
// array (the render tests above use the first; the brick has c / 255).
TEST(BatchShader, TexelDecodesAgree) {
  UvSphere sphere;
  const TriangleMesh mesh = tessellate(sphere);
  const glm::dvec3 eye(0, 0, 4.2);
  std::vector<glm::vec3> p, n;
  std::vector<glm::vec2> uv;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    p.emplace_back(mesh.positions[i] - eye);
    n.emplace_back(mesh.normals[i]);
    uv.emplace_back(mesh.uvs[i] * glm::dvec2(3.0, 2.0));  // several repeats: wrapping
  }
  const BatchMesh bm = batchMesh(p, n, uv, mesh.triangles);
  Scene s = sphereScene();
  s.material.texture = TextureSpec{};
  s.lights = {PointLight{{2, 2, 3}, glm::dvec3(1.0), {}}, AmbientLight{{0.2, 0.2, 0.2}}};
  Texture divided = loadTexture(*s.material.texture);
  ASSERT_TRUE(divided.codes_are_c_over_255);
  Texture table = divided, floats = divided;
  table.codes_are_c_over_255 = false;
  floats.packed.clear();
  floats.codes_are_c_over_255 = false;

  const size_t count = 4000, padded = (count + kBatchPad - 1) / kBatchPad * kBatchPad;
  const test::RandomHits hits = test::randomHits(mesh.triangles.size(), padded, 7);
  std::vector<std::vector<float>> out;
  for (const Texture* t : {&divided, &table, &floats})
    for (TextureFilter f : {TextureFilter::Bilinear, TextureFilter::Nearest}) {
      auto shading = batchShading(s, t, eye);
      ASSERT_TRUE(shading);
      shading->filter = f;
      std::vector<float> r(padded), g(padded), b(padded);
      shadeBatch(*shading, bm, count, hits.tri.data(), hits.b1.data(), hits.b2.data(), r.data(), g.data(),
                 b.data());
      r.insert(r.end(), g.begin(), g.end());
      r.insert(r.end(), b.begin(), b.end());
      out.push_back(std::move(r));
    }
  for (size_t k = 2; k < out.size(); ++k) {
    EXPECT_EQ(0, std::memcmp(out[k].data(), out[k % 2].data(), out[k].size() * sizeof(float))) << k;
  }
  EXPECT_NE(0, std::memcmp(out[0].data(), out[1].data(), out[0].size() * sizeof(float)));  // filters differ
  size_t lit = 0;
  for (float v : out[0]) lit += v > 0.05f && v < 0.95f;
  EXPECT_GT(lit, count);  // the texture shows
}

// The kernel's texture lookup of a uv that is not finite (or beyond float's
// integers) is that of uv 0, as Texture::lookup's: every output equals the
// same mesh's with all uvs 0. Before, the NaN frac became an out-of-range
// texel index in the gather.
TEST(BatchShader, NonFiniteUvLooksUpFracZero) {
  UvSphere sphere;
  const TriangleMesh mesh = tessellate(sphere);
  const glm::dvec3 eye(0, 0, 4.2);
  std::vector<glm::vec3> p, n;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    p.emplace_back(mesh.positions[i] - eye);
    n.emplace_back(mesh.normals[i]);
  }
  Scene s = sphereScene();
  s.material.texture = TextureSpec{};
  s.lights = {PointLight{{2, 2, 3}, glm::dvec3(1.0), {}}, AmbientLight{{0.2, 0.2, 0.2}}};
  const Texture tex = loadTexture(*s.material.texture);
  const size_t count = 1000, padded = (count + kBatchPad - 1) / kBatchPad * kBatchPad;
  const test::RandomHits hits = test::randomHits(mesh.triangles.size(), padded, 11);
  auto shade = [&](float u, TextureFilter f) {
    const std::vector<glm::vec2> uv(mesh.positions.size(), glm::vec2(u, u));
    const BatchMesh bm = batchMesh(p, n, uv, mesh.triangles);
    auto shading = batchShading(s, &tex, eye);
    shading->filter = f;
    std::vector<float> r(padded), g(padded), b(padded);
    shadeBatch(*shading, bm, count, hits.tri.data(), hits.b1.data(), hits.b2.data(), r.data(), g.data(), b.data());
    r.insert(r.end(), g.begin(), g.end());
    r.insert(r.end(), b.begin(), b.end());
    return r;
  };
  const float inf = std::numeric_limits<float>::infinity();
  for (TextureFilter f : {TextureFilter::Nearest, TextureFilter::Bilinear}) {
    const std::vector<float> zero = shade(0.0f, f);
    for (float u : {inf, -inf, std::nanf(""), 3e38f}) {
      SCOPED_TRACE(u);
      EXPECT_EQ(0, std::memcmp(shade(u, f).data(), zero.data(), zero.size() * sizeof(float)));
    }
  }
}
