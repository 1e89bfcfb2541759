#include "scene_file/scene_loader.h"

#include "geometry/model_file.h"
#include "geometry/transform.h"
#include "image/image.h"
#include "image/image_header.h"
#include "image/metric_criteria.h"
#include "scene_file/precision_limits.h"
#include "texture/texture.h"


#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>

namespace xval {

using nlohmann::json;

namespace {

dvec3 requireDirection(JsonReader& r, std::string_view key) {
  dvec3 d = r.requireVec3(key);
  double len = glm::length(d);
  if (!(len > 1e-300) || !std::isfinite(len))
    r.fail(key, "expected a non-zero direction, got [" + std::to_string(d.x) + ", " +
                    std::to_string(d.y) + ", " + std::to_string(d.z) + "]");
  return d;  // kept as written (so a scene round-trips); users normalise
}

Camera readCamera(JsonReader r) {
  Camera c;
  c.position = r.requireVec3("position");
  c.target = r.requireVec3("target");
  c.up = r.vec3("up", c.up);
  c.fov_y_deg = r.number("fov_y_deg", c.fov_y_deg, Range{kMinFovDeg, 180.0, false, true});
  c.width = r.integer("width", c.width, 1, kMaxImageSide);
  c.height = r.integer("height", c.height, 1, kMaxImageSide);
  r.finish();
  if ((long long)c.width * c.height > kMaxImagePixels)
    r.fail("width", "width x height = " + std::to_string((long long)c.width * c.height) +
                        " pixels exceeds the limit of " + std::to_string(kMaxImagePixels));
  dvec3 fwd = c.target - c.position;
  if (!(glm::length(fwd) > 0.0))
    r.fail("target", "target equals position; the camera has no viewing direction");
  if (!(glm::length(c.up) > 0.0)) r.fail("up", "expected a non-zero direction, got [0, 0, 0]");
  double s = glm::length(glm::cross(glm::normalize(fwd), glm::normalize(c.up)));
  if (!(s > 1e-9)) r.fail("up", "is parallel to the viewing direction (target - position)");
  return c;
}

TorusKnot readKnot(JsonReader& r) {
  TorusKnot k;
  k.p = r.integer("p", k.p, 1, 1000);
  k.q = r.integer("q", k.q, 1, 1000);
  if (std::gcd(k.p, k.q) != 1)
    r.fail("q", "p = " + std::to_string(k.p) + " and q = " + std::to_string(k.q) +
                    " are not coprime: that is a torus link, not a knot");
  k.major_radius = r.number("major_radius", k.major_radius, Range::positive());
  k.minor_radius = r.number("minor_radius", k.minor_radius, Range::positive());
  k.tube_radius = r.number("tube_radius", k.tube_radius, Range::positive());
  k.segments_along = r.integer("segments_along", k.segments_along, 3, 1 << 20);
  k.segments_around = r.integer("segments_around", k.segments_around, 3, 1 << 16);
  if ((long long)(k.segments_along + 1) * (k.segments_around + 1) > kMaxMeshVertices)
    r.fail("segments_along", "the mesh would exceed " + std::to_string(kMaxMeshVertices) +
                                 " vertices");
  k.uv_repeat = r.vec2("uv_repeat", k.uv_repeat, Range::positive());
  k.center = r.vec3("center", k.center);
  return k;
}

UvSphere readSphere(JsonReader& r) {
  UvSphere s;
  s.center = r.vec3("center", s.center);
  s.radius = r.number("radius", s.radius, Range::positive());
  s.segments_longitude = r.integer("segments_longitude", s.segments_longitude, 3, 1 << 16);
  s.segments_latitude = r.integer("segments_latitude", s.segments_latitude, 2, 1 << 16);
  if ((long long)(s.segments_longitude + 1) * (s.segments_latitude + 1) > kMaxMeshVertices)
    r.fail("segments_longitude", "the mesh would exceed " + std::to_string(kMaxMeshVertices) +
                                     " vertices");
  s.uv_repeat = r.vec2("uv_repeat", s.uv_repeat, Range::positive());
  return s;
}

Plane readPlane(JsonReader& r) {
  Plane p;
  p.center = r.vec3("center", p.center);
  p.normal = r.has("normal") ? requireDirection(r, "normal") : p.normal;
  p.size = r.vec2("size", p.size, Range::positive());
  p.uv_repeat = r.vec2("uv_repeat", p.uv_repeat, Range::positive());
  return p;
}

Attenuation readAttenuation(JsonReader& r) {
  Attenuation a;
  auto o = r.object("attenuation");
  if (!o) return a;
  // constant > 0 keeps 1/(c + l d + q d^2) finite for a light on the surface.
  a.constant = o->number("constant", a.constant, Range::positive());
  a.linear = o->number("linear", a.linear, Range::nonNegative());
  a.quadratic = o->number("quadratic", a.quadratic, Range::nonNegative());
  o->finish();
  return a;
}

Light readLight(JsonReader r) {
  std::string type = r.requireChoice("type", {"point", "directional", "spot", "ambient"});
  Light out;
  if (type == "point") {
    PointLight l;
    l.position = r.requireVec3("position");
    l.color = r.vec3("color", l.color, Range::nonNegative());
    l.attenuation = readAttenuation(r);
    out = l;
  } else if (type == "directional") {
    DirectionalLight l;
    l.direction = requireDirection(r, "direction");
    l.color = r.vec3("color", l.color, Range::nonNegative());
    out = l;
  } else if (type == "spot") {
    SpotLight l;
    l.position = r.requireVec3("position");
    l.direction = requireDirection(r, "direction");
    l.cutoff_deg = r.number("cutoff_deg", l.cutoff_deg, Range::openClosed(0.0, 90.0));
    l.color = r.vec3("color", l.color, Range::nonNegative());
    l.attenuation = readAttenuation(r);
    out = l;
  } else {
    AmbientLight l;
    l.color = r.vec3("color", l.color, Range::nonNegative());
    out = l;
  }
  r.finish();
  return out;
}

// A model's parameters in its own order (shading/model/params.h), each at
// its default when the field is absent.
template <class M> void readParams(JsonReader& r, M& m) {
  auto range = [](const model::ParamRange& p) { return Range{p.lo, p.hi, p.lo_open, p.hi_open}; };
  model::forEachParam(m, model::Overloaded{
                             [&](const model::NumberParam<M>& p, double& v) { v = r.number(p.name, v, range(p.range)); },
                             [&](const model::ColourParam<M>& p, dvec3& v) { v = r.vec3(p.name, v, range(p.range)); },
                             [&]<class E, size_t N>(const model::ChoiceParam<M, E, N>& p, E& v) {
                               std::array<std::string_view, N> names;
                               for (size_t k = 0; k < N; ++k) names[k] = p.options[k].first;
                               const std::string s = r.choice(p.name, p.nameOf(v), names);
                               for (const auto& [n, e] : p.options)
                                 if (s == n) v = e;
                             }});
}

LightingModel readModel(JsonReader r) {
  const std::string type = r.requireChoice("type", kModelNames);
  LightingModel out;
  for (size_t id = 0; id < kModelCount; ++id)
    if (type == kModelNames[id]) out = defaultModel(ModelId(id));
  std::visit([&](auto& m) { readParams(r, m); }, out);
  r.finish();
  return out;
}

// A path for a message: as a JSON string (quotes and control characters
// escaped, invalid UTF-8 replaced), at most 400 bytes of it.
std::string quotedPath(const std::string& p) {
  const size_t max = 400;
  std::string q = json(p.substr(0, max)).dump(-1, ' ', false, json::error_handler_t::replace);
  return p.size() > max ? q + "..." : q;
}

// The rule for a file a scene names (a texture image, a model file):
// "path" is a non-empty string without NUL, absolute or relative to the
// scene file's folder, naming a regular, readable file.
std::filesystem::path readInputPath(JsonReader& r, const std::filesystem::path& scene_dir, const std::string& what) {
  std::string p = r.requireString("path");
  if (p.empty()) r.fail("path", "expected a file path, got \"\"");
  // A NUL would end the path early in every system call.
  if (p.find('\0') != std::string::npos)
    r.fail("path", "a file path cannot contain a NUL character, got " + describeJson(json(p)));
  std::filesystem::path file = std::filesystem::path(p).is_absolute() ? std::filesystem::path(p) : scene_dir / p;
  const std::string quoted = quotedPath(file.string());
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    r.fail("path", what + " " + quoted + " does not exist or is not a regular file");
  std::ifstream probe(file, std::ios::binary);
  if (!probe) r.fail("path", what + " " + quoted + " is not readable");
  return file;
}

// Opens the image's header (no pixels are read) and checks that the
// texture reader (texture/texture_io.cpp) will accept it.
void checkTextureImage(JsonReader& r, const std::filesystem::path& file, const std::string& quoted) {
  ImageHeader header;
  try {
    header = readImageHeader(file);
  } catch (const std::runtime_error& e) {
    r.fail("path", "texture file " + quoted + " is not an image xval can read: " + e.what());
  }
  const std::string problem = imageHeaderProblem(header, textureLimits());
  if (!problem.empty()) r.fail("path", "texture file " + quoted + " " + problem);
}

TextureSpec readTexture(JsonReader r, const std::filesystem::path& scene_dir) {
  TextureSpec t;
  std::string source = r.requireChoice("source", {"brick", "image", "model"});
  std::string filter = r.choice("filter", "bilinear", {"nearest", "bilinear", "trilinear"});
  t.filter = filter == "nearest"     ? TextureFilter::Nearest
             : filter == "trilinear" ? TextureFilter::Trilinear
                                     : TextureFilter::Bilinear;
  if (source == "image") {
    t.source = TextureSpec::Source::Image;
    t.path = readInputPath(r, scene_dir, "texture file");
    checkTextureImage(r, t.path, quotedPath(t.path.string()));
  } else if (source == "model") {
    // The model file's own textures: checked when the mesh is read
    // (readMeshFile), whose object names the file.
    t.source = TextureSpec::Source::Model;
  } else {
    t.source = TextureSpec::Source::Brick;
  }
  r.finish();
  return t;
}

Material readMaterial(JsonReader r, const std::filesystem::path& scene_dir) {
  Material m;
  m.model = readModel(r.requireObject("model"));
  if (auto t = r.object("texture")) m.texture = readTexture(*t, scene_dir);
  // With source model, base_color colours the primitives without a texture.
  if (r.has("base_color") && m.texture && m.texture->source != TextureSpec::Source::Model)
    r.fail("base_color", "is not used when material.texture is set; remove one of them");
  m.base_color = r.vec3("base_color", m.base_color, Range::nonNegative());
  // The luma-only mode, for any model (colour/luma_only.h); absent: off.
  if (r.has("luma_only")) {
    const std::string space = r.requireChoice("luma_only", kLumaSpaceNames);
    for (size_t k = 0; k < kLumaSpaceNames.size(); ++k)
      if (space == kLumaSpaceNames[k]) m.luma_only = LumaSpace(k);
  }
  r.finish();
  return m;
}

// "transform": scale, rotate, translate (geometry/transform.h); checked
// by toAffine, whose message names the member ("scale[1]: 0 ...").
ObjectTransform readTransform(JsonReader r) {
  ObjectTransform t;
  t.scale = r.numberOrVec3("scale", t.scale);
  if (auto rot = r.object("rotate")) {
    t.rotate.axis = rot->requireVec3("axis");
    t.rotate.angle_deg = rot->requireNumber("angle_deg");
    rot->finish();
  }
  t.translate = r.vec3("translate", t.translate);
  r.finish();
  try {
    (void)toAffine(t);
  } catch (const TransformError& e) {
    const std::string m = e.what();
    const size_t colon = m.find(": ");
    r.fail(m.substr(0, colon), m.substr(colon + 2));
  }
  return t;
}

// "shape": "mesh": the model file at "path", read now (geometry/
// model_file.h) within the scene budget's triangle limit; a textured
// object needs uvs on every primitive, one of texture source "model" on
// every primitive its file textures. Its errors name the field.
MeshFile readMeshFile(JsonReader& r, const std::filesystem::path& scene_dir, const Material& material,
                      const Budget& budget) {
  MeshFile m;
  m.path = readInputPath(r, scene_dir, "model file");
  ModelLoadOptions options;
  options.limits.max_triangles = std::min(options.limits.max_triangles, budget.max_triangles);
  options.uvs = !material.texture                                         ? UvRequirement::None
                : material.texture->source == TextureSpec::Source::Model ? UvRequirement::ModelTextures
                                                                          : UvRequirement::All;
  try {
    m.model = std::make_shared<const Model>(loadModelFile(m.path, options));
  } catch (const ModelFileError& e) {
    r.fail("path", e.what());
  }
  return m;
}

// One of "objects". Its own "material" is read first, so a mesh knows
// whether it must carry uvs; `fallback` is the scene's material (none:
// every object must have its own).
SceneObject readObject(JsonReader r, const std::filesystem::path& scene_dir, const std::optional<Material>& fallback,
                       const Budget& budget) {
  SceneObject out;
  std::string shape = r.requireChoice("shape", {"torus_knot", "sphere", "plane", "mesh"});
  if (auto m = r.object("material")) out.material = readMaterial(*m, scene_dir);
  else if (!fallback)
    r.fail("material", "required field is missing (the scene has no top-level \"material\" to fall back on)");
  if (auto t = r.object("transform")) out.transform = readTransform(*t);
  const Material& mat = out.material ? *out.material : *fallback;
  if (shape != "mesh" && mat.texture && mat.texture->source == TextureSpec::Source::Model) {
    const std::string why = "texture source \"model\" takes the textures a model file assigns, so only a "
                            "\"mesh\" object can use it; this object's shape is \"" + shape + "\"";
    if (out.material) r.fail("material", why);
    r.fail("shape", why + " and it has the scene's material; give it a \"material\" of its own");
  }
  if (shape == "torus_knot") out.shape = readKnot(r);
  else if (shape == "sphere") out.shape = readSphere(r);
  else if (shape == "plane") out.shape = readPlane(r);
  else out.shape = readMeshFile(r, scene_dir, mat, budget);
  r.finish();
  return out;
}

RenderSettings readRender(JsonReader r) {
  RenderSettings s;
  s.spp = r.integer("spp", s.spp, 1, kMaxSpp);
  int n = int(std::lround(std::sqrt(double(s.spp))));
  if (n * n != s.spp)
    r.fail("spp", "expected a perfect square (1, 4, 9, ..., 256: an n x n stratified grid), got " +
                      std::to_string(s.spp));
  std::string p = r.choice("precision", "double", {"float", "double"});
  s.precision = p == "float" ? Precision::Float : Precision::Double;
  r.finish();
  return s;
}

std::function<std::vector<std::string>()>& toleranceRenderers() {
  static std::function<std::vector<std::string>()> ids;
  return ids;
}

std::vector<DeclaredTolerance> readTolerances(JsonReader& r) {
  std::vector<DeclaredTolerance> out;
  auto o = r.object("tolerances");
  if (!o) return out;
  if (!toleranceRenderers())
    r.fail("tolerances", "cannot be checked: this program has no renderer registry (renderers/registry.h)");
  for (const std::string& renderer : toleranceRenderers()()) {
    auto t = o->object(renderer);
    if (!t) continue;
    DeclaredTolerance d;
    d.renderer = renderer;
    if (t->has("max_abs_16bit")) d.max_abs_16bit = t->number("max_abs_16bit", 0, Range::nonNegative());
    if (t->has("fraction")) d.fraction = t->number("fraction", 0, Range::closed(0.0, 1.0));
    if (t->has("max_unexplained_16bit"))
      d.max_unexplained_16bit = t->number("max_unexplained_16bit", 0, Range::nonNegative());
    d.exclude_backfacing = t->boolean("exclude_backfacing", false);
    d.metrics = readMetricCriteria(*t, "metrics");
    d.reason = t->requireString("reason");
    if (d.reason.size() < 20)
      t->fail("reason", "a declared tolerance needs a written reason (at least a sentence), got " +
                            describeJson(json(d.reason)));
    t->finish();
    out.push_back(d);
  }
  o->finish();
  return out;
}

// `findings`: {renderer: why}, each a renderer compared against the
// reference (as `tolerances`), named by `renderers` when the scene has it,
// with a written reason.
std::vector<std::pair<std::string, std::string>> readFindings(JsonReader& r, const std::vector<std::string>& meant_for) {
  std::vector<std::pair<std::string, std::string>> out;
  auto o = r.object("findings");
  if (!o) return out;
  if (!toleranceRenderers())
    r.fail("findings", "cannot be checked: this program has no renderer registry (renderers/registry.h)");
  for (const std::string& renderer : toleranceRenderers()()) {
    if (!o->has(renderer)) continue;
    if (!meant_for.empty() && std::find(meant_for.begin(), meant_for.end(), renderer) == meant_for.end())
      o->fail(renderer, "the scene is not meant for " + renderer + " (its `renderers` field does not name it)");
    const std::string why = o->requireString(renderer);
    if (why.size() < 20)
      o->fail(renderer, "a finding needs a written reason (at least a sentence: what differs and why), got " +
                            describeJson(json(why)));
    out.emplace_back(renderer, why);
  }
  o->finish();
  if (out.empty()) r.fail("findings", "expected at least one renderer's finding, got {}");
  return out;
}

std::function<std::vector<std::string>()>& sceneRenderers() {
  static std::function<std::vector<std::string>()> ids;
  return ids;
}

// `renderers`: at least two distinct registry ids (a comparison needs two).
std::vector<std::string> readRenderers(JsonReader& r) {
  if (!r.has("renderers")) return {};
  const std::vector<std::string> names = r.stringArray("renderers", false);
  if (!sceneRenderers())
    r.fail("renderers", "cannot be checked: this program has no renderer registry (renderers/registry.h)");
  const std::vector<std::string> known = sceneRenderers()();
  std::string listing;
  for (const std::string& id : known) listing += (listing.empty() ? "" : ", ") + id;
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string where = "renderers[" + std::to_string(i) + "]";
    if (std::find(known.begin(), known.end(), names[i]) == known.end())
      r.fail(where, "unknown renderer " + describeJson(json(names[i])) + " (expected one of " + listing + ")");
    if (std::find(names.begin(), names.begin() + i, names[i]) != names.begin() + i)
      r.fail(where, describeJson(json(names[i])) + " named twice");
  }
  if (names.size() < 2)
    r.fail("renderers", "expected at least two renderers (a comparison needs two), got " +
                            std::to_string(names.size()));
  return names;
}

void checkSceneName(JsonReader& r, const std::string& name) {
  const std::string problem = sceneNameProblem(name);
  if (!problem.empty())
    r.fail("name", problem + ", got " + describeJson(json(name)) +
                       (r.has("name") ? "" : " (from the file name; set \"name\")"));
}

}  // namespace

void setToleranceRenderers(std::function<std::vector<std::string>()> ids) { toleranceRenderers() = std::move(ids); }
void setSceneRenderers(std::function<std::vector<std::string>()> ids) { sceneRenderers() = std::move(ids); }

// The name becomes a folder under the output folder (`xval validate`
// writes DIR/NAME/...) and part of paths handed to OpenImageIO and the
// external renderers: one path component that none of them misreads.
std::string sceneNameProblem(const std::string& name, SceneNameUse use) {
  if (name.empty() || name == "." || name == "..") return "expected a name usable as a folder name";
  if (name.find('/') != std::string::npos || name.find('\0') != std::string::npos)
    return "expected a name without '/' or NUL (it becomes a folder name)";
  try {
    (void)json(name).dump();  // throws on invalid UTF-8 (only a file name can hold it)
  } catch (const json::type_error&) {
    return "expected UTF-8 text";
  }
  if (name.size() > kMaxSceneNameBytes)
    return "expected at most " + std::to_string(kMaxSceneNameBytes) + " bytes, got " +
           std::to_string(name.size()) + " bytes in all";
  if (name.find_first_of("\\?") != std::string::npos)
    return "expected a name without '\\' or '?' (Blender reads '\\' as a folder separator and "
           "OpenImageIO reads '?' in a file name as the start of options)";
  if (use == SceneNameUse::Loaded) return "";
  for (unsigned char c : name)
    if (c < 0x20 || c == 0x7f) return "expected no control characters";
  for (const std::string own : kReservedSceneNames)
    if (name == own || name.rfind(own + ".partial-", 0) == 0)
      return "expected none of the names xval validate uses in its output folder (" + own + ")";
  return "";
}

Scene parseScene(const std::string& text, const std::filesystem::path& file, const Budget& budget) {
  const std::string fname = file.string();
  // Syntax errors, duplicate keys, absurd nesting and numbers beyond a
  // double are SceneErrors naming the field (json_reader.h).
  json doc = parseJsonText(text, fname);
  JsonReader r(doc, "", fname);
  Scene s;
  s.source_file = file;
  std::string format = r.string("format", "xval-scene/1");
  if (format != "xval-scene/1")
    r.failValue("format", "\"xval-scene/1\" (the only version this build reads)");
  s.name = r.string("name", file.stem().string());
  checkSceneName(r, s.name);
  s.camera = readCamera(r.requireObject("camera"));
  // The top-level material is every object's default; it may be omitted
  // when every object has its own (then the first object's is the default).
  std::optional<Material> fallback;
  if (auto m = r.object("material")) fallback = readMaterial(*m, file.parent_path());
  auto objects = r.objectArray("objects", true);
  if (objects.empty()) r.fail("objects", "expected at least one object, got []");
  for (auto& o : objects) s.objects.push_back(readObject(o, file.parent_path(), fallback, budget));
  s.material = fallback ? *fallback : *s.objects[0].material;
  for (auto& l : r.objectArray("lights", true)) s.lights.push_back(readLight(l));
  std::string shading = r.choice("shading", "phong", {"flat", "gouraud", "phong"});
  s.shading = shading == "flat"      ? ShadingMode::Flat
              : shading == "gouraud" ? ShadingMode::Gouraud
                                     : ShadingMode::Phong;
  s.normalize_normal = r.boolean("normalize_normal", true);
  if (!s.normalize_normal && s.shading != ShadingMode::Phong)
    r.fail("normalize_normal", std::string("false applies to shading \"phong\" only (the interpolated normal), got "
                                           "shading \"") + toString(s.shading) + "\"");
  // A vertex has no pixel footprint to choose a mip level from.
  for (size_t k = 0; s.shading == ShadingMode::Gouraud && k <= s.objects.size(); ++k) {
    const Material& m = k < s.objects.size() ? materialOf(s, k) : s.material;
    if (m.texture && m.texture->filter == TextureFilter::Trilinear)
      r.fail("shading", "\"gouraud\" evaluates the texture at the vertices, where a trilinear filter has no "
                        "pixel footprint to choose its mip level from; expected \"phong\" or \"flat\" with "
                        "texture filter \"trilinear\"");
  }
  if (auto rs = r.object("render")) s.render = readRender(*rs);
  s.tolerances = readTolerances(r);
  s.renderers = readRenderers(r);
  s.findings = readFindings(r, s.renderers);
  r.finish();
  // Numbers its own precision cannot compute with (scene_file/precision_limits.h).
  checkPrecision(s, s.render.precision);
  // Triangles, samples and memory in all (scene_file/scene_budget.h).
  checkBudget(s, s.render.spp, budget);
  return s;
}


std::string nonSceneReason(const std::filesystem::path& file) {
  if (file.filename() == "tolerances.json") return "a tolerance file";
  std::string text;
  try {
    text = readJsonFile(file, "scene file");
  } catch (const SceneError&) {
    return "";
  }
  json j;
  try {
    j = parseJsonText(text, file.string());
  } catch (const SceneError&) {
    return "";  // loadScene says what is wrong with it
  }
  if (!j.is_object() || !j.contains("format") || !j["format"].is_string()) return "";
  const std::string format = j["format"].get<std::string>();
  if (format.rfind("xval-", 0) == 0 && format.rfind("xval-scene/", 0) != 0)
    return "a file of format " + describeJson(j["format"]) + ", not a scene";
  return "";
}

std::string readJsonFile(const std::filesystem::path& file, const std::string& what) {
  std::error_code ec;
  // Not a FIFO, device or folder: opening one blocks or reads without end.
  if (!std::filesystem::is_regular_file(file, ec))
    throw SceneError(file.string() + ": " + what + " does not exist or is not a regular file");
  const auto bytes = std::filesystem::file_size(file, ec);
  if (!ec && bytes > std::uintmax_t(kMaxSceneFileBytes))
    throw SceneError(file.string() + ": (top level): the " + what + " is " + std::to_string(bytes) +
                     " bytes; the limit is " + std::to_string(kMaxSceneFileBytes));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(file.string() + ": cannot open " + what + " for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw SceneError(file.string() + ": error while reading the " + what);
  return ss.str();
}

Scene loadScene(const std::filesystem::path& file, const Budget& budget) {
  return parseScene(readJsonFile(file, "scene file"), file, budget);
}

const char* toString(ShadingMode m) {
  switch (m) {
    case ShadingMode::Flat: return "flat";
    case ShadingMode::Gouraud: return "gouraud";
    case ShadingMode::Phong: return "phong";
  }
  return "?";
}
const char* toString(Precision p) { return p == Precision::Float ? "float" : "double"; }
const char* toString(TextureFilter f) {
  switch (f) {
    case TextureFilter::Nearest: return "nearest";
    case TextureFilter::Bilinear: return "bilinear";
    case TextureFilter::Trilinear: return "trilinear";
  }
  return "?";
}

}  // namespace xval
