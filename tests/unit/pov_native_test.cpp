// The POV-Ray native tier (povray/pov_native.h): the finish written for
// each model with its exact numbers, the light sources, and every refusal
// with its reason, without running POV-Ray.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "povray/pov_exporter.h"
#include "povray/pov_native.h"
#include "renderers/registry.h"
#include "support/temp_files.h"

using namespace xval;
using namespace xval::pov;

namespace {

Scene nativeScene(LightingModel model) {
  Scene s;
  s.name = "native";
  s.camera.width = s.camera.height = 16;
  s.objects = {UvSphere{}};
  s.material.model = model;
  s.lights = {PointLight{{1, 1, 3}, glm::dvec3(1.0), {}}, AmbientLight{glm::dvec3(0.1)}};
  return s;
}

Material withModel(LightingModel model) {
  Material m;
  m.model = model;
  return m;
}

std::string refusal(const Scene& s) { return renderers::registry().at("povray-native").cannot_express(s); }

}  // namespace

// classic_phong paper: ambient ka diffuse kd phong ks phong_size n (POV-Ray's
// phong is ks max(R.V, 0)^phong_size Lc, white, as the paper's highlight).
TEST(PovNative, ClassicPhongIsDiffuseAndPhong) {
  ClassicPhong m;
  m.ka = 0.9, m.kd = 0.8, m.ks = 0.7, m.shininess = 40;
  EXPECT_EQ(nativeFinishSdl(nativeFinish(withModel(m))),
            "finish { ambient 0.9 diffuse 0.8 brilliance 1 emission 0 phong 0.7 phong_size 40 }");
}

// blinn_phong: specular ks roughness 1/n (POV-Ray's parser stores
// 1/roughness as the exponent of N.H).
TEST(PovNative, BlinnPhongIsSpecularWithRoughnessOneOverN) {
  BlinnPhong m;
  m.ka = 1, m.kd = 0.7, m.ks = 0.6, m.shininess = 80;
  const NativeFinish f = nativeFinish(withModel(m));
  EXPECT_EQ(f.roughness, 1.0 / 80.0);
  EXPECT_EQ(f.phong, 0.0);
  EXPECT_EQ(nativeFinishSdl(f), "finish { ambient 1 diffuse 0.7 brilliance 1 emission 0 specular 0.6 roughness 0.0125 }");
}

// ks = 0: no highlight keyword at all (n is then never used).
TEST(PovNative, NoHighlightWithoutKs) {
  ClassicPhong m;
  m.ks = 0, m.shininess = 0;
  EXPECT_EQ(nativeFinishSdl(nativeFinish(withModel(m))), "finish { ambient 1 diffuse 1 brilliance 1 emission 0 }");
}

TEST(PovNative, LambertAndMinnaert) {
  Lambert l;
  l.c0 = glm::dvec3(0.9);
  EXPECT_EQ(nativeFinishSdl(nativeFinish(withModel(l))), "finish { ambient 1 diffuse 0.9 brilliance 1 emission 0 }");
  Minnaert mi;
  mi.kd = 0.8, mi.k = 2.2;
  EXPECT_EQ(nativeFinishSdl(nativeFinish(withModel(mi))), "finish { ambient 1 diffuse 0.8 brilliance 2.2 emission 0 }");
}

// Lights: POV-Ray has no 1/d^2 of its own; fade gives 2c/(c + q d^2) and
// 2c/(c + l d) exactly, the colour halved; ambient lights sum into
// ambient_light.
TEST(PovNative, LightsByFade) {
  Scene s = nativeScene(ClassicPhong{});
  s.lights = {PointLight{{1, 2, 3}, glm::dvec3(1.0, 0.5, 0.25), {2.0, 0.0, 0.5}},
              SpotLight{{0, 0, 5}, {0, 0, -1}, 20.0, glm::dvec3(1.0), {1.0, 0.25, 0.0}},
              DirectionalLight{{0, 0, -2}, glm::dvec3(0.5)}, AmbientLight{glm::dvec3(0.1)},
              AmbientLight{glm::dvec3(0.05, 0.0, 0.0)}};
  const NativeLights n = nativeLights(s);
  ASSERT_EQ(n.sources.size(), 3u);
  EXPECT_EQ(lightSourceSdl(n.sources[0]),
            "light_source { <1, 2, 3> rgb <0.25, 0.125, 0.0625> fade_distance 2 fade_power 2 }");
  EXPECT_EQ(lightSourceSdl(n.sources[1]),
            "light_source { <0, 0, 5> rgb <0.5, 0.5, 0.5> fade_distance 4 fade_power 1 spotlight point_at <0, 0, 4> "
            "radius 20 falloff 20 tightness 0 }");
  EXPECT_EQ(lightSourceSdl(n.sources[2]), "light_source { <-0, -0, 1> rgb <0.5, 0.5, 0.5> parallel point_at <0, 0, 0> }");
  EXPECT_DOUBLE_EQ(n.ambient_light.x, 0.15);
  EXPECT_DOUBLE_EQ(n.ambient_light.y, 0.1);
}

// The export writes the finish, the ambient_light and no double_illuminate
// (POV-Ray's own gate is part of what the tier compares).
TEST(PovNative, ExportWritesTheFinish) {
  Scene s = nativeScene(BlinnPhong{0.5, 0.7, 0.6, 80});
  const auto dir = test::freshTempDir("xval_pov_native_export");
  const PovExport ex = exportPov(s, dir, "scene.png", PovTier::Native);
  const std::string sdl = test::fileText(ex.pov);
  EXPECT_NE(sdl.find("ambient_light rgb <0.1, 0.1, 0.1>"), std::string::npos) << sdl;
  EXPECT_NE(sdl.find("pigment { rgb <1, 1, 1> }"), std::string::npos) << sdl;
  EXPECT_NE(sdl.find("finish { ambient 0.5 diffuse 0.7 brilliance 1 emission 0 specular 0.6 roughness 0.0125 }"),
            std::string::npos)
      << sdl;
  EXPECT_NE(sdl.find("light_source { <1, 1, 3> rgb <1, 1, 1> }"), std::string::npos) << sdl;
  EXPECT_EQ(sdl.find("double_illuminate"), std::string::npos) << sdl;
  EXPECT_EQ(sdl.find("slope"), std::string::npos) << sdl;  // no emission pigments
}

TEST(PovNative, RendererIsRestricted) {
  const renderers::Renderer& r = renderers::registry().at("povray-native");
  EXPECT_FALSE(r.every_scene);
  EXPECT_EQ(refusal(nativeScene(ClassicPhong{})), "");
}

// Each refusal names what and why.
TEST(PovNative, RefusesWhatItCannotExpress) {
  ClassicPhong course;
  course.variant = ClassicPhong::Variant::Course;
  EXPECT_NE(refusal(nativeScene(course)).find("material.model: classic_phong variant course is not expressible natively"),
            std::string::npos);
  ClassicPhong n0;
  n0.shininess = 0;
  EXPECT_NE(refusal(nativeScene(n0)).find("classic_phong: shininess 0 with ks 1"), std::string::npos);
  EXPECT_NE(refusal(nativeScene(BlinnPhong{1, 1, 1, 0})).find("blinn_phong: shininess 0"), std::string::npos);
  Lambert coloured;
  coloured.c0 = {1.0, 0.5, 0.5};
  EXPECT_NE(refusal(nativeScene(coloured)).find("lambert with c0 <1, 0.5, 0.5> (not grey)"), std::string::npos);
  EXPECT_NE(refusal(nativeScene(WrapAround{})).find("wrap_around has no built-in POV-Ray finish"), std::string::npos);
  EXPECT_NE(refusal(nativeScene(YiqLuma{})).find("yiq_luma has no built-in POV-Ray finish"), std::string::npos);
  EXPECT_NE(refusal(nativeScene(OrenNayar{})).find("oren_nayar has no built-in"), std::string::npos);
  EXPECT_NE(refusal(nativeScene(CookTorrance{})).find("cook_torrance has no built-in"), std::string::npos);

  Scene gouraud = nativeScene(ClassicPhong{});
  gouraud.shading = ShadingMode::Gouraud;
  EXPECT_NE(refusal(gouraud).find("shading \"gouraud\" is not expressible natively"), std::string::npos);

  Scene luma = nativeScene(ClassicPhong{});
  luma.material.luma_only = LumaSpace::Yiq;
  EXPECT_NE(refusal(luma).find("material.luma_only is not expressible natively"), std::string::npos);

  // 1/(1 + 0.2 d + 0.05 d^2): complex roots, no sum of fades gives it.
  Scene att = nativeScene(ClassicPhong{});
  att.lights = {PointLight{{1, 1, 3}, glm::dvec3(1.0), {1.0, 0.2, 0.05}}};
  EXPECT_NE(refusal(att).find("lights[0].attenuation 1/(1 + 0.2 d + 0.05 d^2) is not expressible natively"),
            std::string::npos)
      << refusal(att);
}
