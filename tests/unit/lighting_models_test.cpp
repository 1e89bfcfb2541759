// The lighting-model registry (shading/model/registry.h) against every
// place that handles models: each model of the registry round-trips
// through the scene loader and writer with every parameter, has its
// numbers checked by the precision limits, a GLSL id that the shaders
// test, its glTF constants for the Blender harness, a node graph in that
// harness (render_gltf.py), and a case in the shading cases that the
// shader, gl and Blender-graph tests run.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "gl/glsl_models.h"
#include "gltf/shading_constants.h"
#include "scene_file/precision_limits.h"
#include "scene_file/scene_loader.h"
#include "scene_file/scene_writer.h"
#include "shading/model/registry.h"
#include "support/shading_cases.h"

namespace {

using namespace xval;
using nlohmann::ordered_json;

std::vector<ModelId> allModels() {
  std::vector<ModelId> ids;
  for (size_t id = 0; id < kModelCount; ++id) ids.push_back(ModelId(id));
  return ids;
}

// The model with every parameter moved off its default, within its range
// (numbers by +1/8 or to the middle of a closed range; colours per
// channel; a choice to its last option), and the scene-file JSON of it.
std::pair<LightingModel, ordered_json> offDefault(ModelId id) {
  LightingModel m = defaultModel(id);
  ordered_json j = {{"type", kModelNames[size_t(id)]}};
  std::visit(
      [&]<class M>(M& mm) {
        model::forEachParam(mm, model::Overloaded{
                                    [&](const model::NumberParam<M>& p, double& v) {
                                      v = v + 0.125 <= p.range.hi ? v + 0.125 : (p.range.lo + p.range.hi) / 2;
                                      j[p.name] = v;
                                    },
                                    [&](const model::ColourParam<M>& p, glm::dvec3& v) {
                                      v += glm::dvec3(0.125, 0.25, 0.375);
                                      j[p.name] = {v.x, v.y, v.z};
                                    },
                                    [&]<class E, size_t N>(const model::ChoiceParam<M, E, N>& p, E& v) {
                                      v = p.options[N - 1].second;
                                      j[p.name] = p.options[N - 1].first;
                                    }});
      },
      m);
  return {m, j};
}

std::string sceneText(const ordered_json& model) {
  ordered_json s = {{"camera", {{"position", {0, 0, 4}}, {"target", {0, 0, 0}}, {"width", 8}, {"height", 8}}},
                    {"objects", ordered_json::array({{{"shape", "sphere"}}})},
                    {"material", {{"model", model}}},
                    {"lights", ordered_json::array({{{"type", "point"}, {"position", {0, 3, 3}}}})}};
  return s.dump();
}

Scene sceneWith(const ordered_json& model) { return parseScene(sceneText(model), "registry_test.json"); }

TEST(LightingModels, NamesAreUniqueAndIdsAreTheVariantsOrder) {
  std::set<std::string_view> names(kModelNames.begin(), kModelNames.end());
  EXPECT_EQ(names.size(), kModelCount);
  for (ModelId id : allModels()) {
    const LightingModel m = defaultModel(id);
    EXPECT_EQ(m.index(), size_t(id));
    EXPECT_EQ(modelId(m), id);
    EXPECT_EQ(std::string_view(modelName(m)), kModelNames[size_t(id)]);
  }
}

TEST(LightingModels, EveryModelRoundTripsThroughTheLoaderAndTheWriter) {
  for (ModelId id : allModels()) {
    SCOPED_TRACE(kModelNames[size_t(id)]);
    // Defaults: the type alone loads as the model's default, and the writer
    // writes every parameter.
    const Scene d = sceneWith({{"type", kModelNames[size_t(id)]}});
    EXPECT_EQ(sceneToJson(d)["material"]["model"], sceneToJson(sceneWith(sceneToJson(d)["material"]["model"]))["material"]["model"]);
    // Every parameter off its default: read, written back in the same order.
    const auto [m, j] = offDefault(id);
    const Scene s = sceneWith(j);
    EXPECT_EQ(s.material.model.index(), size_t(id));
    EXPECT_EQ(sceneToJson(s)["material"]["model"], j);
    EXPECT_NE(sceneToJson(d)["material"]["model"], j) << "no parameter moved off its default";
  }
}

TEST(LightingModels, AnUnknownTypeIsRefusedListingEveryModel) {
  try {
    sceneWith({{"type", "no_such_model"}});
    ADD_FAILURE() << "an unknown model loaded";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("material.model.type"), std::string::npos) << what;
    for (auto name : kModelNames) EXPECT_NE(what.find("\"" + std::string(name) + "\""), std::string::npos) << what;
  }
}

TEST(LightingModels, ThePrecisionLimitsCheckEveryParameter) {
  for (ModelId id : allModels()) {
    Scene s = sceneWith({{"type", kModelNames[size_t(id)]}});
    std::visit(
        [&]<class M>(M& mm) {
          model::forEachParam(mm, [&](const auto& p, auto& v) {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, double> || std::is_same_v<V, glm::dvec3>) {
              const V saved = v;
              v = V(1e31);  // beyond float's 1e30 for a number
              const std::string field = std::string("material.model.") + p.name +
                                        (std::is_same_v<V, glm::dvec3> ? "[0]" : "");
              try {
                checkPrecision(s, Precision::Float);
                ADD_FAILURE() << kModelNames[size_t(id)] << "." << p.name << " = 1e31 passed";
              } catch (const SceneError& e) {
                EXPECT_NE(std::string(e.what()).find(field + ": 1e+31"), std::string::npos) << e.what();
              }
              v = saved;
            }
          });
        },
        s.material.model);
  }
}

TEST(LightingModels, EveryModelHasAGlslIdThatBothShadersTest) {
  for (ModelId id : allModels()) {
    const std::string c = gl::glslModelConstant(id);
    SCOPED_TRACE(c);
    gl::ShaderVariant v;
    v.model = id;
    const std::string vs = gl::vertexShaderSource(v), fs = gl::fragmentShaderSource(v);
    const std::string decl = "const int " + c + " = " + std::to_string(size_t(id)) + ";";
    EXPECT_NE(vs.find(decl), std::string::npos);
    EXPECT_NE(fs.find(decl), std::string::npos);
    // The program of a draw of this model is specialised to it.
    EXPECT_NE(vs.find("const int k_model = " + c + ";"), std::string::npos);
    EXPECT_NE(fs.find("const int k_model = " + c + ";"), std::string::npos);
    EXPECT_NE(vs.find("k_model == " + c + ")"), std::string::npos) << "the shaders have no case for it";
    EXPECT_EQ(vs.find("k_model == 0"), std::string::npos) << "a model tested by a literal id";
  }
}

TEST(LightingModels, EveryModelHasItsGltfConstants) {
  for (ModelId id : allModels()) {
    SCOPED_TRACE(kModelNames[size_t(id)]);
    const Scene s = sceneWith(offDefault(id).second);
    const ordered_json k = shadingConstants(s);
    EXPECT_EQ(k["model"], kModelNames[size_t(id)]);
    std::visit(
        [&]<class M>(const M& mm) {
          model::forEachParam(mm, model::Overloaded{
                                      [&](const model::NumberParam<M>& p, double v) { EXPECT_EQ(k.value(p.name, -1.0), v) << p.name; },
                                      [&](const model::ColourParam<M>& p, const glm::dvec3& v) {
                                        EXPECT_EQ(k.value(p.name, ordered_json()), ordered_json({v.x, v.y, v.z})) << p.name;
                                      },
                                      [](const auto&, const auto&) {}});  // a choice: the harness's own flags
        },
        s.material.model);
  }
}

// The names in one of render_gltf.py's tuples `NAME = ("a", "b", ...)`.
std::set<std::string> pythonTuple(const std::string& text, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex("\n" + name + R"( = \(([^)]*)\))"))) return {};
  std::set<std::string> out;
  const std::string body = m[1];
  const std::regex item(R"re("([a-z_0-9]+)")re");
  for (auto it = std::sregex_iterator(body.begin(), body.end(), item); it != std::sregex_iterator(); ++it)
    out.insert((*it)[1]);
  return out;
}

TEST(LightingModels, TheBlenderHarnessBuildsEveryModel) {
  const std::string path = std::string(XVAL_TESTS_DIR) + "/../exporters/blender/render_gltf.py";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::stringstream text;
  text << in.rdbuf();
  std::set<std::string> known = pythonTuple(text.str(), "PHONG_MODELS");
  const std::set<std::string> forsyth = pythonTuple(text.str(), "FORSYTH_MODELS");
  known.insert(forsyth.begin(), forsyth.end());
  // issue #33's minnaert, blinn_phong, oren_nayar; cook_torrance
  const std::set<std::string> issue33 = pythonTuple(text.str(), "MINNAERT_BLINN_OREN_NAYAR_MODELS");
  known.insert(issue33.begin(), issue33.end());
  const std::set<std::string> microfacet = pythonTuple(text.str(), "MICROFACET_MODELS");
  known.insert(microfacet.begin(), microfacet.end());
  const std::set<std::string> registry(kModelNames.begin(), kModelNames.end());
  EXPECT_EQ(known, registry) << path << ": PHONG_MODELS + FORSYTH_MODELS + MINNAERT_BLINN_OREN_NAYAR_MODELS + MICROFACET_MODELS";
}

TEST(LightingModels, TheShadingCasesCoverEveryModel) {
  test::CaseRng r(1);
  std::set<size_t> covered;
  for (const auto& [name, m] : test::lightingModels(r)) covered.insert(m.index());
  for (ModelId id : allModels()) EXPECT_TRUE(covered.count(size_t(id))) << kModelNames[size_t(id)];
}

TEST(LightingModels, TheSceneFormatDocumentsEveryParameter) {
  const std::string path = std::string(XVAL_TESTS_DIR) + "/../docs/scene-format.md";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::map<std::string, std::string> rows;  // "| `type` | fields |" by type
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, std::regex(R"(\| `([a-z_0-9]+)` \|(.*))"))) rows.emplace(m[1], m[2]);
  }
  for (ModelId id : allModels()) {
    const std::string name(kModelNames[size_t(id)]);
    ASSERT_TRUE(rows.count(name)) << path << " has no row for model " << name;
    std::visit(
        [&](const auto& mm) {
          model::forEachParam(mm, [&](const auto& p, const auto&) {
            EXPECT_NE(rows[name].find("`" + std::string(p.name) + "`"), std::string::npos)
                << path << ": model " << name << " without its parameter " << p.name;
          });
        },
        defaultModel(id));
  }
}

}  // namespace

// The shaders' YIQ functions are generated from colour/yiq.h's matrices:
// they print the listing's coefficients as the listing does (the text the
// gl renderer compiled before they were generated, so its images are
// unchanged), in both stages.
TEST(LightingModels, TheShadersYiqFunctionsAreTheListingsMatrices) {
  const std::string expected =
      "vec3 rgbToYiq(vec3 c) {\n"
      "  return vec3(0.29889531 * c.r + 0.58662247 * c.g + 0.11448223 * c.b,\n"
      "              0.59597799 * c.r + -0.27417610 * c.g + -0.32180189 * c.b,\n"
      "              0.21147017 * c.r + -0.52261711 * c.g + 0.31114694 * c.b);\n"
      "}\n"
      "vec3 yiqToRgb(vec3 yiq) {  // without the listing's saturate: the frame saturates once\n"
      "  return vec3(yiq.x + 0.95608445 * yiq.y + 0.62088850 * yiq.z,\n"
      "              yiq.x - 0.27137664 * yiq.y - 0.64860590 * yiq.z,\n"
      "              yiq.x - 1.10561724 * yiq.y + 1.70250126 * yiq.z);\n"
      "}\n";
  const gl::ShaderVariant v;
  EXPECT_NE(gl::vertexShaderSource(v).find(expected), std::string::npos) << gl::vertexShaderSource(v);
  EXPECT_NE(gl::fragmentShaderSource(v).find(expected), std::string::npos);
}
