// Every number of a scene, set to values at and beyond the edges of float
// and double (scene_file/precision_limits.h): either the loader or the renderer
// refuses it with a message naming the field, or both precisions render it
// without a NaN, and the float image agrees with the double one. A silent
// wrong image (the float path's inf x 0 = NaN, saturated to black where
// double gives white) fails.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/renderer.h"
#include "scene_file/precision_limits.h"
#include "scene_file/scene_loader.h"

using namespace xval;
using nlohmann::json;

namespace {

// Every model, with every light kind and every shape in view; textured or
// with a base colour.
std::vector<json> baseScenes() {
  const json lights = json::parse(R"([
    {"type": "point", "position": [-0.5, 2, 1.25], "color": [0.8, 0.7, 0.6],
     "attenuation": {"constant": 1, "linear": 0.1, "quadratic": 0.05}},
    {"type": "directional", "direction": [0.3, -1, -0.5], "color": [0.5, 0.5, 0.5]},
    {"type": "spot", "position": [0, 0, 3], "direction": [0, 0, -1], "cutoff_deg": 30,
     "color": [0.6, 0.6, 0.6], "attenuation": {"constant": 1, "linear": 0.2, "quadratic": 0.1}},
    {"type": "ambient", "color": [0.1, 0.1, 0.1]}])");
  const json objects = json::parse(R"([
    {"shape": "torus_knot", "p": 2, "q": 3, "major_radius": 0.6, "minor_radius": 0.25, "tube_radius": 0.12,
     "segments_along": 48, "segments_around": 6, "uv_repeat": [12, 2], "center": [-0.8, 0.4, 0]},
    {"shape": "sphere", "center": [0.8, 0.4, 0], "radius": 0.5, "segments_longitude": 12,
     "segments_latitude": 6, "uv_repeat": [1, 1]},
    {"shape": "plane", "center": [0, -0.6, -0.5], "normal": [0, 0.5, 1], "size": [3, 1.5], "uv_repeat": [2, 1]}])");
  const json models[] = {
      {{"type", "classic_phong"}, {"variant", "paper"}, {"ka", 1}, {"kd", 1}, {"ks", 1}, {"shininess", 55}},
      {{"type", "classic_phong"}, {"variant", "course"}, {"ka", 0.5}, {"kd", 1}, {"ks", 1}, {"shininess", 20}},
      {{"type", "yiq_luma"}, {"kd", 1}, {"ks", 1}, {"shininess", 55}, {"luma_offset", 0.1}},
      {{"type", "lambert"}, {"c0", {0.9, 0.8, 0.7}}},
      {{"type", "wrap_around"}, {"c0", {0.9, 0.8, 0.7}}, {"factor", 0.5}},
      {{"type", "hemispherical"}, {"c0", {0.9, 0.8, 0.7}}, {"c2", {0.1, 0.2, 0.3}}},
      {{"type", "bidirectional"}, {"c0", {0.9, 0.8, 0.7}}, {"c2", {0.1, 0.2, 0.3}}},
      {{"type", "trilight"}, {"c0", {0.9, 0.8, 0.7}}, {"c1", {0.2, 0.2, 0.2}}, {"c2", {0.1, 0.2, 0.3}}}};
  std::vector<json> out;
  for (size_t k = 0; k < std::size(models); ++k) {
    json material = {{"model", models[k]}};
    if (k == 0 || k == 2) material["texture"] = {{"source", "brick"}, {"filter", k == 2 ? "nearest" : "bilinear"}};
    else material["base_color"] = {0.7, 0.6, 0.5};
    out.push_back({{"name", "limits" + std::to_string(k)},
                   {"camera", {{"position", {0, 0.3, 4}}, {"target", {0, 0, 0}}, {"up", {0, 1, 0}},
                               {"fov_y_deg", 45}, {"width", 12}, {"height", 10}}},
                   {"objects", objects},
                   {"material", material},
                   {"lights", lights},
                   {"shading", k % 3 == 0 ? "phong" : k % 3 == 1 ? "gouraud" : "flat"}});
  }
  return out;
}

// The path of every number in j ("lights[0].color[1]"), and a pointer to it.
void numbers(json& j, const std::string& path, std::vector<std::pair<std::string, json*>>& out) {
  if (j.is_number()) {
    out.push_back({path, &j});
  } else if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) numbers(it.value(), path.empty() ? it.key() : path + "." + it.key(), out);
  } else if (j.is_array()) {
    for (size_t i = 0; i < j.size(); ++i) numbers(j[i], path + "[" + std::to_string(i) + "]", out);
  }
}

// "lights[0].color[1]" -> "lights[0].color": messages name the field.
std::string field(const std::string& path) {
  return path.back() == ']' ? path.substr(0, path.rfind('[')) : path;
}

bool hasNan(const Image& img) {
  for (float v : img.rgba) if (std::isnan(v)) return true;
  for (float v : img.raw) if (std::isnan(v)) return true;
  return false;
}
bool hasNonFinite(const Image& img) {
  for (float v : img.rgba) if (!std::isfinite(v)) return true;
  for (float v : img.raw) if (!std::isfinite(v)) return true;
  return false;
}

// Pixels where the two images' coverage differs, or a covered pixel's
// colour differs by more than 4/255 in some channel.
int disagreements(const Image& a, const Image& b) {
  int n = 0;
  for (size_t i = 0; i < a.rgba.size() / 4; ++i) {
    const bool ha = a.rgba[i * 4 + 3] > 0, hb = b.rgba[i * 4 + 3] > 0;
    if (ha != hb) { ++n; continue; }
    for (int c = 0; c < 3; ++c)
      if (std::abs(a.rgba[i * 4 + c] - b.rgba[i * 4 + c]) > 4.0f / 255.0f) { ++n; break; }
  }
  return n;
}

}  // namespace

TEST(PrecisionLimits, EveryNumberAtTheEdgesIsRefusedByNameOrRenderedAlike) {
  const double values[] = {1e39, 3.5e38, -1e300, 1e-300, 1e-39, 1e13};
  std::vector<json> bases = baseScenes();
  int rendered = 0, refused = 0;
  std::vector<std::string> problems;
  for (size_t s = 0; s < bases.size(); ++s) {
    std::vector<std::pair<std::string, json*>> leaves;
    numbers(bases[s], "", leaves);
    for (auto& entry : leaves) {
      const std::string path = entry.first;  // a named copy: lambdas below capture it
      json* leaf = entry.second;
      // Camera, objects and lights are the same in every base scene.
      if (s > 0 && path.rfind("material", 0) != 0 && path != "camera.position[0]") continue;
      const json saved = *leaf;
      for (double v : values) {
        *leaf = v;
        const std::string what = bases[s]["name"].get<std::string>() + " " + path + " = " + json(v).dump();
        auto refusedByName = [&](const SceneError& e) {
          ++refused;
          // A camera point may be refused for its relation to the others
          // ("camera.up: is parallel to the viewing direction (target - position)").
          const std::string named = path.rfind("camera.", 0) == 0 ? "camera." : field(path);
          if (std::string(e.what()).find(named) == std::string::npos)
            problems.push_back(what + ": refused without naming " + field(path) + ": " + e.what());
        };
        Scene scene;
        try {
          scene = parseScene(bases[s].dump(), "limits.json");
        } catch (const SceneError& e) {
          refusedByName(e);
          continue;
        }
        // What renderScene checks first (and the double render costs).
        try {
          checkPrecision(scene, Precision::Float);
        } catch (const SceneError& e) {
          refusedByName(e);
          continue;
        }
        Image img[2];
        for (int p = 0; p < 2; ++p) {
          RenderOptions o;
          o.precision = p == 0 ? Precision::Double : Precision::Float;
          o.threads = 1;
          img[p] = renderScene(scene, o);
        }
        ++rendered;
        if (hasNan(img[0])) problems.push_back(what + ": NaN in the double render");
        if (hasNonFinite(img[1])) problems.push_back(what + ": NaN or inf in the float render");
        const int d = disagreements(img[0], img[1]);
        if (d > 3) problems.push_back(what + ": float and double disagree on " + std::to_string(d) + " pixels");
      }
      *leaf = saved;
    }
  }
  for (const auto& p : problems) ADD_FAILURE() << p;
  std::printf("%d rendered, %d refused\n", rendered, refused);
  EXPECT_GT(rendered, 50);
  EXPECT_GT(refused, 100);
}

// The cases the float path turned into NaN (black where double gives
// white), refused for float with the file, the field, the value and the
// limit: when the scene declares float, by the loader; when it declares
// double and is rendered in float (--precision float), by the renderer.
TEST(PrecisionLimits, FloatRefusesWhatItCannotComputeWithByName) {
  std::vector<json> bases = baseScenes();
  struct Case { size_t scene; const char* pointer; double value; const char* field; };
  const Case cases[] = {{0, "/lights/0/color/0", 1e39, "lights[0].color[0]: 1e+39"},
                        {0, "/lights/0/attenuation/constant", 1e-300, "lights[0].attenuation.constant"},
                        {0, "/material/model/ks", 1e300, "material.model.ks"},
                        {2, "/material/model/kd", 1e300, "material.model.kd"},
                        {0, "/objects/1/uv_repeat/0", 1e39, "objects[1].uv_repeat[0]: 1e+39"}};
  auto expectNamed = [](const std::string& m, const Case& c) {
    EXPECT_NE(m.find("limits.json: "), std::string::npos) << m;
    EXPECT_NE(m.find(c.field), std::string::npos) << m;
    EXPECT_NE(m.find("float precision"), std::string::npos) << m;
  };
  int rendered_in_double = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.pointer);
    json j = bases[c.scene];
    j[json::json_pointer(c.pointer)] = c.value;
    j["render"] = {{"precision", "float"}};
    try {
      parseScene(j.dump(), "limits.json");
      ADD_FAILURE() << "loaded in float";
    } catch (const SceneError& e) {
      expectNamed(e.what(), c);
    }
    j["render"] = {{"precision", "double"}};
    Scene s;
    try {
      s = parseScene(j.dump(), "limits.json");
    } catch (const SceneError&) {
      continue;  // beyond double as well (the sweep above checks the message)
    }
    ++rendered_in_double;
    RenderOptions o;
    o.precision = Precision::Float;
    try {
      renderScene(s, o);
      ADD_FAILURE() << "rendered in float";
    } catch (const SceneError& e) {
      expectNamed(e.what(), c);
    }
  }
  EXPECT_GE(rendered_in_double, 2);
}
