// The extremes matrix (validate/extremes/matrix.h, measure.h, docs/extremes.md) and the
// formulation fixes its cases showed. Each fix has a test in which the old
// formula gives a large error (or a vanished light) and the new one not:
//   - clamp(R.V)^n from |R - V| (models::phongSpecular; case specular_n1e6);
//   - L and d without overflow of (p_light - p)^2 (towardsLight; case
//     light_far_1e20);
//   - camera-relative shading coordinates (Shader's origin; case
//     offset_1e6);
//   - cook_torrance's V.H from |L + V| (case
//     ct_beckmann_vgroove_schlick_grazing) and GGX's D as (alpha / q)^2 / pi
//     (case ct_ggx_alpha_min), models::cookTorranceSpecular.
// Then what the scene format cannot express, on hand-made data: zero-area
// triangles through the intersector in both precisions, and a zero-length
// normal and a NaN eye vector (the eye at the shaded point) through every
// model. Last, the whole matrix at 40 x 40: no NaN/Inf in either precision,
// and float within 64/65535 of double except where a documented cause
// decides pixels by the last bit.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "geometry/mesh.h"
#include "render/accel.h"
#include "scene_file/precision_limits.h"
#include "scene_file/scene_loader.h"
#include "shading/lights.h"
#include "shading/models.h"
#include "shading/shader.h"
#include "validate/extremes/matrix.h"
#include "validate/extremes/measure.h"
#include "support/temp_files.h"

using namespace xval;
namespace m = xval::models;

// --- clamp(R.V)^n at n = 1e6 in float --------------------------------------

// R at an angle theta from V = +z, both rounded to float as the float path
// has them. Exact: cos(theta)^n. The listing's form rounds R.V to float
// first; near 1 its ulp is 6e-8, and n = 1e6 turns that into a relative
// error of up to exp(1e6 x 6e-8) - 1 = 6%.
TEST(ExtremesFix, SpecularFromRMinusVKeepsHighShininessInFloat) {
  const double n = 1e6;
  double worst_old = 0.0, worst_new = 0.0;
  for (double theta = 1e-4; theta < 2.5e-3; theta += 1.7e-5) {  // S from 1 down to ~0.04
    const glm::vec3 r(float(std::sin(theta)), 0.0f, float(std::cos(theta)));
    const glm::vec3 v(0.0f, 0.0f, 1.0f);
    const double exact = std::exp(n * std::log(std::cos(theta)));
    const double old_form = m::phongSpecular(glm::dot(r, v), float(n));
    const double new_form = m::phongSpecular(r, v, float(n));
    worst_old = std::max(worst_old, std::abs(old_form - exact) / exact);
    worst_new = std::max(worst_new, std::abs(new_form - exact) / exact);
  }
  EXPECT_GT(worst_old, 0.02) << "the listing's form in float (the bug the case showed)";
  EXPECT_LT(worst_new, 1e-4);
}

TEST(ExtremesFix, SpecularFromRMinusVAgreesWithTheListingFormInDouble) {
  for (double theta = 0.0; theta < 3.2; theta += 0.01)
    for (double n : {0.0, 0.5, 1.0, 55.0, 1e3}) {
      const glm::dvec3 r(std::sin(theta), 0.0, std::cos(theta)), v(0, 0, 1);
      EXPECT_NEAR(m::phongSpecular(r, v, n), m::phongSpecular(std::cos(theta), n), 1e-12)
          << "theta " << theta << " n " << n;
    }
}

TEST(ExtremesFix, SpecularSpecialValues) {
  const glm::dvec3 v(0, 0, 1), zero(0), nan(std::nan(""));
  EXPECT_EQ(m::phongSpecular(glm::dvec3(1, 0, 0), v, 0.0), 1.0);   // pow(0, 0) = 1
  EXPECT_EQ(m::phongSpecular(glm::dvec3(0, 0, -1), v, 0.0), 1.0);  // R.V < 0, n = 0
  EXPECT_EQ(m::phongSpecular(glm::dvec3(0, 0, -1), v, 55.0), 0.0);
  EXPECT_EQ(m::phongSpecular(zero, v, 55.0), 0.0);  // R = 0: a light at the point
  EXPECT_EQ(m::phongSpecular(v, v, 1e6), 1.0);
  EXPECT_EQ(m::phongSpecular(v, nan, 55.0), 0.0);  // V = NaN: the eye at the point
}

// --- a light 1e20 away, and one 1e-21 away, in float ------------------------

TEST(ExtremesFix, LightVectorWithoutOverflowOrUnderflowInFloat) {
  for (float scale : {1e20f, 1e30f, 1e-21f, 1e-30f}) {
    const glm::vec3 D = glm::vec3(-0.5f, 2.0f, 1.25f) * scale;
    // The old formula: d = |D| = sqrt(D.D).
    const float old_d = glm::length(D);
    const glm::vec3 old_L = old_d > 0.0f ? D / old_d : glm::vec3(0.0f);
    glm::vec3 L;
    float d;
    towardsLight(D, L, d);
    const glm::dvec3 exact = glm::normalize(glm::dvec3(-0.5, 2.0, 1.25));
    // Overflow: the old L is 0 (the light vanishes); underflow: it is 0
    // (D.D = 0) or off by ~1e-4 (D.D subnormal).
    EXPECT_GT(glm::length(glm::dvec3(old_L) - exact), 5e-5) << "scale " << scale << ": old L";
    EXPECT_LT(glm::length(glm::dvec3(L) - exact), 1e-6) << "scale " << scale;
    EXPECT_NEAR(double(d) / (double(scale) * std::sqrt(0.25 + 4.0 + 1.5625)), 1.0, 1e-6);
  }
  glm::vec3 L;
  float d;
  towardsLight(glm::vec3(0.0f), L, d);  // the light at the point
  EXPECT_EQ(d, 0.0f);
  EXPECT_EQ(L, glm::vec3(0.0f));
}

// towardsLightMayRescale: the gl renderer leaves the rescaling out where it
// says no, so it must say yes wherever a point of the box could need it.
TEST(ExtremesFix, LightMayRescaleOnlyNearOrFarFromTheBox) {
  const glm::dvec3 lo(-1.0), hi(1.0);
  EXPECT_FALSE(towardsLightMayRescale(glm::dvec3(-0.5, 2.0, 1.25), lo, hi));  // Table 2's light, the knot's box
  EXPECT_TRUE(towardsLightMayRescale(glm::dvec3(0.0), lo, hi));               // inside the box
  EXPECT_TRUE(towardsLightMayRescale(glm::dvec3(1.0 + 1e-5, 0.0, 0.0), lo, hi));  // within the margin
  EXPECT_FALSE(towardsLightMayRescale(glm::dvec3(1.0 + 1e-3, 0.0, 0.0), lo, hi));
  EXPECT_TRUE(towardsLightMayRescale(glm::dvec3(0.0, 1e20, 0.0), lo, hi));  // docs/extremes.md light_far_1e20
  EXPECT_TRUE(towardsLightMayRescale(glm::dvec3(0.0, 0.0, 1e-21), glm::dvec3(0.0), glm::dvec3(0.0)));
  EXPECT_TRUE(towardsLightMayRescale(glm::dvec3(std::nan(""), 0.0, 0.0), lo, hi));
  // Where it says no, every corner of the box (and so every point of it)
  // takes towardsLight's usual path in float.
  for (double far : {2.0, 1e6, 1e14})
    for (double size : {1e-3, 1.0, 1e4}) {
      const glm::dvec3 light(0.3 * far, far, -0.2 * far), a(-size), b(size);
      if (towardsLightMayRescale(light, a, b)) continue;
      for (int k = 0; k < 8; ++k) {
        const glm::vec3 corner((k & 1) ? b.x : a.x, (k & 2) ? b.y : a.y, (k & 4) ? b.z : a.z);
        const glm::vec3 D = glm::vec3(light) - corner;
        const float dd = glm::dot(D, D);
        EXPECT_TRUE(dd >= std::numeric_limits<float>::min() && dd <= std::numeric_limits<float>::max())
            << far << " " << size;
      }
    }
}

TEST(ExtremesFix, PointLightFarAwayStillLightsInFloat) {
  Material mat;
  mat.model = Lambert{};
  const glm::dvec3 far = glm::normalize(glm::dvec3(-0.5, 2.0, 1.25)) * 1e20;
  Shader<float> sh(mat, {PointLight{far, glm::dvec3(1.0), {}}});
  const glm::vec3 c = sh.shade(glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), glm::vec3(1));
  EXPECT_NEAR(c.x, glm::normalize(glm::dvec3(-0.5, 2.0, 1.25)).z, 1e-6);
}

// --- camera-relative coordinates 1e6 from the world origin, in float ----------

// A point of the offset_1e6 sphere, shaded in float (a) in world
// coordinates, with the position rounded to float as the float path's
// interpolation of world vertices gives it (ulp 0.0625 at 1e6), and (b)
// relative to the eye (subtracted in double, then rounded): against the
// double world shading.
TEST(ExtremesFix, CameraRelativeShadingKeepsFloatPrecisionFarFromTheOrigin) {
  const glm::dvec3 o(1e6, 1e6, 1e6), eye = o + glm::dvec3(0, 0, 4.25);
  Material mat;
  mat.model = ClassicPhong{};
  const std::vector<Light> lights = {PointLight{o + glm::dvec3(-0.5, 2.0, 1.25), glm::dvec3(1.0), {1.0, 0.1, 0.05}},
                                     AmbientLight{}};
  const Shader<double> ref(mat, lights);
  const Shader<float> world(mat, lights), relative(mat, lights, eye);
  double worst_world = 0.0, worst_relative = 0.0;
  for (double a = -1.2; a <= 1.2; a += 0.05) {
    const glm::dvec3 n(std::sin(a) * 0.6, std::cos(a) * 0.3, 0.0);
    const glm::dvec3 nn = glm::normalize(n + glm::dvec3(0, 0, 0.8));
    const glm::dvec3 p = o + nn;
    const glm::dvec3 c = ref.shade(p, nn, glm::normalize(eye - p), glm::dvec3(0.7, 0.5, 0.3));
    const glm::vec3 pw(p), ew(eye);
    const glm::vec3 cw = world.shade(pw, glm::vec3(nn), glm::normalize(ew - pw), glm::vec3(0.7f, 0.5f, 0.3f));
    const glm::vec3 pr(p - eye);
    const glm::vec3 cr = relative.shade(pr, glm::vec3(nn), glm::normalize(-pr), glm::vec3(0.7f, 0.5f, 0.3f));
    for (int k = 0; k < 3; ++k) {
      worst_world = std::max(worst_world, std::abs(double(cw[k]) - c[k]));
      worst_relative = std::max(worst_relative, std::abs(double(cr[k]) - c[k]));
    }
  }
  EXPECT_GT(worst_world * 65535.0, 100.0) << "world coordinates in float (the bug the case showed)";
  EXPECT_LT(worst_relative * 65535.0, 1.0);
}

// --- cook_torrance: V.H at grazing, and GGX's peak at the smallest alpha ----------

// L and V nearly opposite, both grazing over N = +z (case
// ct_beckmann_vgroove_schlick_grazing: the light 2e-4 rad above the plane's
// far side, the eye 1e-4 to 1e-2 rad above its near side): the float path's
// L and V (unit in double, rounded to float: unit to ~6e-8) against the
// double path's. V.H = |L + V| / 2 for unit L and V. The old form
// dot(v, normalize(l + v)) = (L.V + |V|^2) / |L + V| turns the rounding of
// |V|^2 - 1 (~1e-7) into an error of 1e-7 / |L + V| ~ 1e-3 of V.H ~ 1e-4.
TEST(ExtremesFix, CookTorranceVdotHFromTheLengthOfLPlusV) {
  const glm::dvec3 ld = glm::normalize(glm::dvec3(0.0, std::cos(2e-4), std::sin(2e-4))), nd(0, 0, 1);
  const glm::vec3 l(ld), n(nd);
  double worst_old = 0.0, worst_new = 0.0, worst_s = 0.0;
  for (double ev = 1e-4; ev < 1e-2; ev *= 1.13)
    for (double vx : {0.0, 1e-4, 3e-4, 1e-3}) {
      const glm::dvec3 vd = glm::normalize(glm::dvec3(vx, -1.0, ev));
      const glm::vec3 v(vd);
      const double exact = 0.5 * glm::length(ld + vd);
      const glm::vec3 sum = l + v;
      const float len = glm::length(sum);
      const float old_form = glm::dot(v, sum / len);
      const float new_form = 0.5f * len;  // what models::cookTorranceSpecular forms
      worst_old = std::max(worst_old, std::abs(old_form - exact) / exact);
      worst_new = std::max(worst_new, std::abs(new_form - exact) / exact);
      // Through S (the V-groove's 2 N.H / V.H, Schlick's (1 - V.H)^5).
      const double want = m::cookTorranceSpecular(nd, ld, vd, m::MicrofacetD::Beckmann, m::MicrofacetG::VGroove,
                                                  m::MicrofacetF::Schlick, 0.5, 0.04);
      const float got = m::cookTorranceSpecular(n, l, v, m::MicrofacetD::Beckmann, m::MicrofacetG::VGroove,
                                                m::MicrofacetF::Schlick, 0.5f, 0.04f);
      if (want > 1e-6) worst_s = std::max(worst_s, std::abs(got - want) / want);
    }
  EXPECT_GT(worst_old, 1e-2) << "dot(v, h) in float (the bug the case showed)";
  EXPECT_LT(worst_new, 1e-6);
  EXPECT_LT(worst_s, 1e-5);
}

// GGX's D at its peak (sin^2(N, H) = 0, N.H = 1) is 1 / (pi alpha^2). At the
// smallest alpha float accepts with ks = 1 (case ct_ggx_alpha_min) the old
// form alpha^2 / (pi q^2), q = alpha^2, squares q below float's smallest
// subnormal: inf. Formed as (alpha / q)^2 / pi it is finite and exact to
// float's precision, at the peak and around it.
TEST(ExtremesFix, CookTorranceGgxPeakWithoutUnderflowInFloat) {
  const float alpha = 2.3e-12f, a2 = alpha * alpha, q = a2;
  const float old_peak = a2 / (3.14159265f * q * q);
  EXPECT_TRUE(std::isinf(old_peak)) << "the old form in float (the bug the case showed): " << old_peak;
  for (double s2 : {0.0, 1e-25, 1e-23, 1e-21, 1e-12}) {
    const double c = std::sqrt(1.0 - s2);
    const double want = m::microfacetD(m::MicrofacetD::Ggx, c, s2, double(alpha));
    const float got = m::microfacetD(m::MicrofacetD::Ggx, float(c), float(s2), alpha);
    EXPECT_TRUE(std::isfinite(got)) << s2;
    EXPECT_NEAR(got, want, 1e-6 * want) << s2;
  }
}

// The alpha of the ct_*_alpha_min cases is the smallest float accepts (to
// two digits): the case's scene passes float's precision limits, and the
// same scene with alpha 2.2e-12 is refused, whatever ks: S (up to
// specularGain ~ 2.66 / alpha^3) is formed before ks multiplies it, so a
// small ks does not let a smaller alpha through (ks 1e-30 and alpha 3e-22
// gave a raw Inf in float: S = 1 / (4 alpha^2 N.V) > FLT_MAX).
TEST(Extremes, CookTorranceAlphaMinIsTheSmallestFloatAccepts) {
  for (const auto& c : extremes::extremesMatrix({40})) {
    if (c.name.find("_alpha_min") == std::string::npos) continue;
    SCOPED_TRACE(c.name);
    nlohmann::ordered_json j = c.scene;
    EXPECT_EQ(j["material"]["model"]["roughness"].get<double>(), 2.3e-12);
    EXPECT_NO_THROW(checkPrecision(parseScene(j.dump(), c.name + ".json"), Precision::Float));
    j["material"]["model"]["roughness"] = 2.2e-12;
    EXPECT_THROW(checkPrecision(parseScene(j.dump(), c.name + ".json"), Precision::Float), SceneError);
    for (double ks : {0.5, 1e-30}) {
      j["material"]["model"]["ks"] = ks;
      EXPECT_THROW(checkPrecision(parseScene(j.dump(), c.name + ".json"), Precision::Float), SceneError) << ks;
    }
  }
}

// --- what the scene format cannot express --------------------------------------

// Zero-area triangles (three coincident vertices; three collinear ones) next
// to a proper one: rays through them find nothing, in both precisions, and
// the proper triangle is still found.
TEST(ExtremesDegenerate, ZeroAreaTrianglesAreNeverHit) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},              // proper
                 {5, 5, 0}, {5, 5, 0}, {5, 5, 0},              // one point
                 {2, -1, 0}, {3, -1, 0}, {4, -1, 0}};          // on a line
  m.normals.assign(9, glm::dvec3(0, 0, 1));
  m.normals[4] = glm::dvec3(0, 0, -1);  // opposite normals: their average is 0
  m.uvs.assign(9, glm::dvec2(0));
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  const std::vector<TriangleMesh> meshes = {m};  // Accel keeps pointers into it
  for (Precision prec : {Precision::Double, Precision::Float}) {
    Accel accel(meshes, prec);
    const glm::dvec3 down(0, 0, -1);
    EXPECT_TRUE(accel.intersect({0.25, 0.25, 1}, down).hit);
    for (glm::dvec3 o : {glm::dvec3(5, 5, 1), glm::dvec3(3, -1, 1), glm::dvec3(2.5, -1, 1)})
      EXPECT_FALSE(accel.intersect(o, down).hit) << toString(prec) << " at " << o.x << ", " << o.y;
    // A ray along the line of the collinear triangle, in its plane.
    EXPECT_FALSE(accel.intersect({0, -1, 0}, {1, 0, 0}).hit) << toString(prec);
  }
}

// A zero-length normal (what the renderer keeps for a zero interpolated
// normal) and V = NaN (normalize(eye - p) with p at the eye) through every
// model and light type: finite colours.
TEST(ExtremesDegenerate, ZeroNormalAndNanEyeVectorGiveFiniteColours) {
  const std::vector<LightingModel> models = {
      ClassicPhong{}, ClassicPhong{ClassicPhong::Variant::Course, 1, 1, 1, 0.0}, YiqLuma{},
      Lambert{}, WrapAround{}, Hemispherical{}, BiDirectional{}, Trilight{}};
  const std::vector<Light> lights = {PointLight{{0, 0, 0}, glm::dvec3(1), {1e-9, 0, 1}},  // at p
                                     SpotLight{{0, 1, 0}, {0, -1, 0}, 30, glm::dvec3(1), {}},
                                     DirectionalLight{{0, -1, 0}, glm::dvec3(1)}, AmbientLight{}};
  const glm::dvec3 nan(std::nan(""));
  for (const auto& model : models) {
    Material mat;
    mat.model = model;
    const Shader<double> sd(mat, lights);
    const Shader<float> sf(mat, lights);
    for (glm::dvec3 n : {glm::dvec3(0), glm::dvec3(0, 1, 0)})
      for (glm::dvec3 v : {nan, glm::dvec3(0, 1, 0)}) {
        const glm::dvec3 cd = sd.shade(glm::dvec3(0), n, v, glm::dvec3(0.5));
        const glm::vec3 cf = sf.shade(glm::vec3(0), glm::vec3(n), glm::vec3(v), glm::vec3(0.5f));
        for (int k = 0; k < 3; ++k) {
          EXPECT_TRUE(std::isfinite(cd[k])) << modelName(model) << " n.y " << n.y << " v.y " << v.y;
          EXPECT_TRUE(std::isfinite(cf[k])) << modelName(model) << " n.y " << n.y << " v.y " << v.y;
        }
      }
  }
}

// --- the matrix ------------------------------------------------------------------

// Every case at 40 x 40 (41 x 41 for the odd ones): each scene file loads
// (and so renders with `xval render`), neither precision has a NaN or Inf
// in its final or raw channels, and float is within 64/65535 of double,
// except in the cases whose float-vs-double difference is decided by the
// last bit (docs/extremes.md says why for each).
TEST(Extremes, MatrixHasNoNanOrInfAndFloatFollowsDouble) {
  const std::set<std::string> last_bit = {
      "spot_cone_edge",         // pixel centres exactly on the hard cone's edge
      "eye_on_surface",         // rays start on a surface: hits at t = +-rounding
      "eye_at_vertex_phong",    // float accepts the hit at t = 0 on the cap around the eye
      "eye_at_vertex_gouraud",  // (the same)
      "degenerate_sphere_far"};  // coincident twin triangles: which one is hit is rounding
  const auto dir = xval::test::freshTempDir("xval_extremes_test");
  std::filesystem::remove_all(dir);
  const auto cases = extremes::extremesMatrix({40});
  const auto files = extremes::writeCaseScenes(cases, dir / "scenes");
  ASSERT_EQ(files.size(), cases.size());
  std::set<std::string> names;
  for (size_t k = 0; k < cases.size(); ++k) {
    SCOPED_TRACE(cases[k].name);
    EXPECT_TRUE(names.insert(cases[k].name).second) << "duplicate case name";
    const Scene scene = loadScene(files[k]);
    const auto dbl = extremes::renderReference(scene, Precision::Double, 0);
    const auto flt = extremes::renderReference(scene, Precision::Float, 0);
    EXPECT_EQ(dbl.nonfinite.final_pixels, 0);
    EXPECT_EQ(dbl.nonfinite.raw_pixels, 0);
    EXPECT_EQ(flt.nonfinite.final_pixels, 0);
    EXPECT_EQ(flt.nonfinite.raw_pixels, 0);
    if (last_bit.count(cases[k].name)) continue;
    const CompareMetrics fd = extremes::compareToReference(dbl.image, flt.image);
    EXPECT_LT(fd.max_abs * 65535.0, 64.0);
    EXPECT_EQ(fd.mask_disagree, fd.mask_disagree_explained);
  }
  std::filesystem::remove_all(dir);
}

// NaN and Inf are counted per pixel, in the final and the raw channels.
TEST(Extremes, CountNonFiniteSeesFinalAndRawChannels) {
  Image img(3, 1, true);
  img.rgba[0 * 4 + 1] = std::nanf("");
  img.raw[1 * 3 + 2] = std::numeric_limits<float>::infinity();
  img.raw[2 * 3 + 0] = std::nanf("");
  img.raw[2 * 3 + 1] = -std::numeric_limits<float>::infinity();
  const auto n = extremes::countNonFinite(img);
  EXPECT_EQ(n.final_pixels, 1);
  EXPECT_EQ(n.raw_pixels, 2);
}

// --only: the named cases in matrix order (not the order given), every
// case when empty, and an unknown name is an error that lists the cases.
TEST(Extremes, SelectCasesByName) {
  const auto all = extremes::extremesMatrix({16});
  ASSERT_GE(all.size(), 3u);
  EXPECT_EQ(extremes::selectCases(all, "").size(), all.size());
  const auto two = extremes::selectCases(all, all[2].name + "," + all[0].name + ",");
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].name, all[0].name);
  EXPECT_EQ(two[1].name, all[2].name);
  try {
    extremes::selectCases(all, all[0].name + ",no_such_case");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no case named no_such_case"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(all.back().name), std::string::npos) << e.what();
  }
}
