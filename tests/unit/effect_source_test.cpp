// shader_file/effect_source.h: the tool's edits of an HLSL effect, on the
// paper's listing as printed (reference/shaders) and on small effects.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "shader_file/effect_source.h"

namespace xval::shaderfile {
namespace {

std::string listing() {
  std::ifstream in(std::string(XVAL_REFERENCE_DIR) + "/shaders/kotsarenko2012_table1.fx", std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool saysAt(const PreparedEffect& p, int line, const std::string& what) {
  return std::any_of(p.edits.begin(), p.edits.end(),
                     [&](const SourceEdit& e) { return e.line == line && e.what.find(what) != std::string::npos; });
}

TEST(EffectSource, TheListingsEditsKeepItsLines) {
  const std::string text = listing();
  const PreparedEffect p = prepareEffect(text, "PhongVertexShader");
  EXPECT_EQ(std::count(p.text.begin(), p.text.end(), '\n'), std::count(text.begin(), text.end(), '\n'));
  ASSERT_EQ(p.edits.size(), 5u);
  EXPECT_TRUE(saysAt(p, 27, "texture declaration \"ColorTexture\""));
  EXPECT_TRUE(saysAt(p, 32, "sampler_state initialiser of \"ColorSampler\""));
  EXPECT_TRUE(saysAt(p, 39, "POSITION read as SV_Position"));
  EXPECT_TRUE(saysAt(p, 91, "repeated declaration \"float3 LightVector = normalize(LightPos - PosWorld);\""));
  EXPECT_TRUE(saysAt(p, 118, "not closed"));
  // One LightVector declaration left; no technique, texture or sampler_state.
  size_t n = 0;
  for (size_t at = p.text.find("float3 LightVector"); at != std::string::npos; at = p.text.find("float3 LightVector", at + 1)) ++n;
  EXPECT_EQ(n, 1u);
  EXPECT_EQ(p.text.find("technique"), std::string::npos);
  EXPECT_EQ(p.text.find("sampler_state"), std::string::npos);
  EXPECT_EQ(p.text.find("texture ColorTexture"), std::string::npos);
  EXPECT_NE(p.text.find("sampler2D ColorSampler"), std::string::npos);
}

TEST(EffectSource, TheListingsBindings) {
  const PreparedEffect p = prepareEffect(listing(), "PhongVertexShader");
  ASSERT_EQ(p.globals.size(), 7u);
  EXPECT_EQ(p.globals[4].name, "LightPos");
  EXPECT_EQ(p.globals[4].semantic, "Position");
  EXPECT_EQ(p.globals[4].object, "PointLight0");
  EXPECT_EQ(p.globals[5].name, "AmbientValue");
  EXPECT_EQ(p.globals[5].semantic, "");
  ASSERT_EQ(p.textures.size(), 1u);
  EXPECT_EQ(p.textures[0].semantic, "DIFFUSE");
  ASSERT_EQ(p.samplers.size(), 1u);
  EXPECT_EQ(p.samplers[0].texture, "ColorTexture");
  EXPECT_EQ(p.samplers[0].states.at("FILTER"), "MIN_MAG_MIP_LINEAR");
  ASSERT_EQ(p.passes.size(), 1u);
  EXPECT_EQ(p.passes[0].states.size(), 7u);
  ASSERT_EQ(p.vertex_inputs.size(), 3u);
  EXPECT_EQ(p.vertex_inputs[1].glsl_name, "InpTex");
  EXPECT_EQ(p.vertex_inputs[1].semantic, "TEXCOORD0");
}

TEST(EffectSource, OnlyAnIdenticalRepeatWithoutSideEffectsIsRemoved) {
  const std::string differs = "float f(float x) { float a = x; float a = x + 1; return a; }\n";
  EXPECT_TRUE(prepareEffect(differs, "VS").edits.empty());
  const std::string assigns = "float f(float x) { float a = x = 2; float a = x = 2; return a; }\n";
  EXPECT_TRUE(prepareEffect(assigns, "VS").edits.empty());
  const std::string increments = "float f(float x) { float a = x++; float a = x++; return a; }\n";
  EXPECT_TRUE(prepareEffect(increments, "VS").edits.empty());
  const std::string apart = "float f(float x) { float a = x; { } float a = x; return a; }\n";
  EXPECT_TRUE(prepareEffect(apart, "VS").edits.empty());
  const std::string same = "float f(float x) { float a = x * 2;\n  float a = x * 2; return a; }\n";
  const PreparedEffect p = prepareEffect(same, "VS");
  ASSERT_EQ(p.edits.size(), 1u);
  EXPECT_EQ(p.edits[0].line, 2);
}

TEST(EffectSource, AnUnclosedCommentOrBlockNamesItsLine) {
  try {
    prepareEffect("float4 a;\n/* no end\n", "VS");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("line 2: a /* comment is not closed"), std::string::npos) << e.what();
  }
  try {
    prepareEffect("float4 a;\nfloat f() { return 1;\n", "VS");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace xval::shaderfile
