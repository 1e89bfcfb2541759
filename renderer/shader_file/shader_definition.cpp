// A user's shader's definition file (shader_file/shader_definition.h).
#include "shader_file/shader_definition.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "scene/json_reader.h"
#include "scene_file/scene_writer.h"

namespace xval::shaderfile {

namespace fs = std::filesystem;

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper((unsigned char)c));
  return s;
}

std::string quantityNames() {
  std::string out;
  for (const Quantity& q : kQuantities) out += (out.empty() ? "" : ", ") + std::string(q.name);
  return out;
}

const char* lookup(const std::pair<const char*, const char*>* b, const std::pair<const char*, const char*>* e,
                   const std::string& key) {
  for (auto* p = b; p != e; ++p)
    if (key == p->first) return p->second;
  return nullptr;
}

// The source, confined to the definition's folder: relative, no "..", not
// through a link leading out, a regular file of at most kMaxShaderSourceBytes.
fs::path confinedSource(JsonReader& r, const fs::path& definition, const std::string& source) {
  const fs::path rel(source);
  if (source.empty() || rel.is_absolute())
    r.fail("source", "\"" + source + "\": expected a path relative to the definition file's folder");
  for (const fs::path& part : rel)
    if (part == "..") r.fail("source", "\"" + source + "\": '..' is refused (the source must be inside " +
                                           definition.parent_path().string() + ")");
  std::error_code ec;
  const fs::path folder = fs::canonical(definition.parent_path(), ec);
  const fs::path path = fs::canonical(definition.parent_path() / rel, ec);
  if (ec) r.fail("source", "\"" + source + "\": cannot be read (" + ec.message() + ")");
  const std::string f = folder.string() + "/";
  if (path.string().compare(0, f.size(), f) != 0)
    r.fail("source", "\"" + source + "\": leads out of " + folder.string() + " (to " + path.string() +
                         ") through a link; the source must be inside the definition's folder");
  if (!fs::is_regular_file(path)) r.fail("source", "\"" + source + "\": not a regular file");
  if (fs::file_size(path) > kMaxShaderSourceBytes)
    r.fail("source", "\"" + source + "\": larger than " + std::to_string(kMaxShaderSourceBytes) + " bytes");
  return path;
}

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  if (!in && !in.eof()) throw SceneError(p.string() + ": cannot be read");
  return ss.str();
}

// The filter a sampler's states ask for: "nearest", "bilinear",
// "trilinear", "scene" (no filter state), or "" with `problem` set.
std::string samplerFilter(const EffectSampler& s, std::string& problem) {
  auto state = [&](const char* k) {
    auto it = s.states.find(k);
    return it == s.states.end() ? std::string() : upper(it->second);
  };
  for (const auto& [k, v] : s.states)
    if (k != "FILTER" && k != "MINFILTER" && k != "MAGFILTER" && k != "MIPFILTER" && k != "ADDRESSU" &&
        k != "ADDRESSV") {
      problem = "the state " + k + " = " + v + " (xval applies FILTER, MinFilter, MagFilter, MipFilter, "
                "AddressU and AddressV)";
      return "";
    }
  for (const char* a : {"ADDRESSU", "ADDRESSV"})
    if (const std::string v = state(a); !v.empty() && v != "WRAP") {
      problem = std::string(a) + " = " + v + " (the scenes' textures repeat: only Wrap)";
      return "";
    }
  const std::string f = state("FILTER");
  if (!f.empty()) {
    if (f == "MIN_MAG_MIP_LINEAR") return "trilinear";
    problem = "FILTER = " + f + " (xval applies MIN_MAG_MIP_LINEAR; other filters have no scene counterpart)";
    return "";
  }
  const std::string mn = state("MINFILTER"), mg = state("MAGFILTER"), mp = state("MIPFILTER");
  if (mn.empty() && mg.empty() && mp.empty()) return "scene";
  if (mn == "LINEAR" && mg == "LINEAR" && mp == "LINEAR") return "trilinear";
  if (mn == "LINEAR" && mg == "LINEAR" && (mp == "NONE" || mp.empty())) return "bilinear";
  if (mn == "POINT" && mg == "POINT" && (mp == "NONE" || mp.empty())) return "nearest";
  problem = "MinFilter " + mn + ", MagFilter " + mg + ", MipFilter " + mp +
            " (xval applies Linear/Linear/Linear, Linear/Linear/None and Point/Point/None)";
  return "";
}

}  // namespace

const Quantity* findQuantity(const std::string& name) {
  for (const Quantity& q : kQuantities)
    if (name == q.name) return &q;
  return nullptr;
}

namespace {
// The material's model as the scene file writes it (scene_file/scene_writer.h).
nlohmann::json modelJson(const Material& material) {
  Scene one;
  one.material = material;
  return nlohmann::json::parse(sceneToJson(one)["material"]["model"].dump());
}
}  // namespace

double modelParameter(const Material& material, const std::string& key) {
  const nlohmann::json model = modelJson(material);
  if (!model.contains(key) || !model[key].is_number())
    throw std::runtime_error("the " + model.value("type", std::string("?")) + " model has no parameter \"" + key +
                             "\"");
  return model[key].get<double>();
}

ShaderDefinition loadShaderDefinition(const fs::path& file, const nlohmann::json& doc) {
  JsonReader r(doc, "", file.string());
  ShaderDefinition d;
  d.file = fs::absolute(file).lexically_normal();
  if (r.requireString("format") != kShaderFileFormat) r.failValue("format", std::string("\"") + kShaderFileFormat + "\"");
  d.name = r.requireString("name");
  if (r.has("description")) d.description = r.requireString("description");
  const std::string source = r.requireString("source");
  d.language = r.requireChoice("language", {"hlsl", "glsl"});
  const bool glsl = d.language == "glsl";
  d.vertex_entry = r.requireString("vertex_entry");
  d.fragment_entry = r.requireString("fragment_entry");
  if (glsl)
    for (const char* key : {"vertex_entry", "fragment_entry"})
      if (r.requireString(key) != "main") r.failValue(key, "\"main\" (a GLSL stage's entry point)");
  // GLSL: the fragment stage is "source", the vertex stage "vertex_source";
  // the vertex inputs are mapped by name (GLSL has no semantics).
  std::string vertex_source;
  if (glsl) vertex_source = r.requireString("vertex_source");
  if (glsl) {
    r.requireObject("attributes");
    for (const auto& [k, v] : doc["attributes"].items()) {
      const std::string what = v.is_string() ? v.get<std::string>() : "";
      if (what != "position" && what != "normal" && what != "uv")
        throw SceneError(file.string() + ": attributes." + k + ": " + describeJson(v) +
                         ": expected \"position\", \"normal\" or \"uv\"");
      d.attribute_input[k] = what;
    }
  }
  if (r.has("timeout_s")) d.timeout_s = r.requireNumber("timeout_s", Range::openClosed(0.0, 3600.0));
  const std::string texture_filter = r.choice("texture_filter", "effect", {"effect", "scene"});
  if (r.has("normalize_normal")) d.normalize_normal = r.boolean("normalize_normal", true);
  {
    JsonReader m = r.requireObject("model");
    m.requireString("type");  // the keys are checked against a scene's model, not here
    d.model = doc["model"];
    for (const auto& [k, v] : d.model.items())
      if (k != "type" && !v.is_number() && !v.is_string())
        m.fail(k, "expected a number or a string (the value the shader hard-codes)");
  }
  if (r.has("uniforms")) {
    r.requireObject("uniforms");
    for (const auto& [k, v] : doc["uniforms"].items()) {
      if (!v.is_string() || !findQuantity(v.get<std::string>()))
        throw SceneError(file.string() + ": uniforms." + k + ": " + describeJson(v) + ": expected one of " +
                         quantityNames());
      d.uniform_quantity[k] = v.get<std::string>();
    }
  }
  r.finish();
  d.source = confinedSource(r, d.file, source);
  if (glsl) {
    d.vertex_source = confinedSource(r, d.file, vertex_source);
    // Each uniform is bound by "uniforms" (checked against the compiled
    // program's); a sampler mapped to diffuse_texture reads the material's
    // texture with the scene's filter (GLSL has no sampler state).
    for (const auto& [u, q] : d.uniform_quantity)
      if (findQuantity(q)->type == QuantityType::Sampler) d.samplers.push_back({u, "scene"});
    return d;
  }

  const std::string where = d.source.string();
  try {
    d.effect = prepareEffect(readText(d.source), d.vertex_entry);
  } catch (const std::runtime_error& e) {
    throw SceneError(where + ": " + e.what());
  }

  // The pass's states: applied (entry points checked, depth, no blending, no culling) or refused.
  if (d.effect.passes.size() > 1)
    throw SceneError(where + ": line " + std::to_string(d.effect.passes[1].line) + ": " +
                     std::to_string(d.effect.passes.size()) + " passes; xval draws one");
  for (const EffectPass& p : d.effect.passes)
    for (const auto& state : p.states) {
      const std::string& key = state.first;
      const std::string& value = state.second;
      const std::string k = upper(key), v = upper(value);
      auto refuse = [&](const std::string& why) {
        throw SceneError(where + ": line " + std::to_string(p.line) + ": pass " + p.pass + ": " + key + " = " +
                         value + ": " + why);
      };
      if (k == "VERTEXSHADER" || k == "PIXELSHADER") {
        const std::string& entry = k == "VERTEXSHADER" ? d.vertex_entry : d.fragment_entry;
        if (value.find(entry + "(") == std::string::npos)
          refuse("the definition's " + std::string(k == "VERTEXSHADER" ? "vertex_entry" : "fragment_entry") +
                 " is \"" + entry + "\"");
      } else if (k == "ZENABLE" || k == "ZWRITEENABLE") {
        if (v != "TRUE" && v != "1") refuse("xval reads the hit mask from the depth buffer: it must be on");
      } else if (k == "ZFUNC") {
        if (v == "LESS") d.pipeline.depth_less_equal = false;
        else if (v != "LESSEQUAL") refuse("xval applies Less and LessEqual (near is depth 0)");
      } else if (k == "ALPHABLENDENABLE") {
        if (v != "FALSE" && v != "0") refuse("blending is not applied (each pixel is its nearest surface)");
      } else if (k == "CULLMODE") {
        if (v != "NONE") refuse("xval draws both faces (CullMode = None): the scenes' winding is not D3D's");
      } else {
        refuse("a render state xval does not apply (it applies VertexShader, PixelShader, ZEnable, "
               "ZWriteEnable, ZFunc, AlphaBlendEnable, CullMode)");
      }
    }

  // Every global uniform: bound by "uniforms", else by its semantic.
  for (const EffectGlobal& g : d.effect.globals) {
    if (d.uniform_quantity.count(g.name)) continue;
    if (const char* q = lookup(std::begin(kSemantics), std::end(kSemantics), upper(g.semantic))) {
      d.uniform_quantity[g.name] = q;
      continue;
    }
    throw SceneError(where + ": line " + std::to_string(g.line) + ": the uniform \"" + g.name + "\"" +
                     (g.semantic.empty() ? " has no semantic" : " has the semantic " + g.semantic + ", which xval does not bind,") +
                     " and " + d.file.string() + " does not map it in \"uniforms\": nothing binds it (map it to one of " +
                     quantityNames() + ")");
  }
  for (const auto& [u, q] : d.uniform_quantity)
    if (findQuantity(q)->type == QuantityType::Sampler)
      throw SceneError(d.file.string() + ": uniforms." + u + ": \"" + q + "\" is a texture: bind it with a "
                       "texture declaration's DIFFUSE semantic");
  // Samplers: the texture each reads, its filter.
  for (const EffectSampler& s : d.effect.samplers) {
    const auto tex = std::find_if(d.effect.textures.begin(), d.effect.textures.end(),
                                  [&](const EffectTexture& t) { return t.name == s.texture; });
    if (tex == d.effect.textures.end() || upper(tex->semantic) != "DIFFUSE")
      throw SceneError(where + ": line " + std::to_string(s.line) + ": the sampler \"" + s.name + "\" reads " +
                       (s.texture.empty() ? "no texture" : "the texture \"" + s.texture + "\"") +
                       ", which has no DIFFUSE semantic: nothing binds it");
    std::string problem;
    std::string filter = samplerFilter(s, problem);
    if (filter.empty())
      throw SceneError(where + ": line " + std::to_string(s.line) + ": the sampler \"" + s.name + "\": " + problem);
    if (texture_filter == "scene") filter = "scene";
    d.samplers.push_back({s.name, filter});
  }
  for (const EntryInput& in : d.effect.vertex_inputs) {
    const char* what = lookup(std::begin(kVertexSemantics), std::end(kVertexSemantics), upper(in.semantic));
    if (!what)
      throw SceneError(where + ": the vertex entry " + d.vertex_entry + "'s input \"" + in.glsl_name + "\" has " +
                       (in.semantic.empty() ? "no semantic" : "the semantic " + in.semantic) +
                       "; xval supplies POSITION, NORMAL and TEXCOORD0");
    d.attribute_input[in.glsl_name] = what;
  }
  return d;
}

std::string shaderCannotExpress(const ShaderDefinition& d, const Scene& scene) {
  auto bound = [&](const char* q) {
    return std::any_of(d.uniform_quantity.begin(), d.uniform_quantity.end(),
                       [q](const auto& e) { return e.second == q; });
  };
  int points = 0;
  bool ambient = false;
  for (const Light& l : scene.lights) {
    if (const auto* p = std::get_if<PointLight>(&l)) {
      ++points;
      if (!p->attenuation.isNone()) return d.name + " has no attenuation: the scene's point light is attenuated";
      if (p->color != dvec3(1.0) && !bound("light_color"))
        return d.name + " binds no light colour: the scene's point light is not white";
    } else if (std::holds_alternative<AmbientLight>(l)) {
      ambient = true;
    } else {
      return d.name + " lights with one point light: the scene has a " +
             std::string(std::holds_alternative<SpotLight>(l) ? "spot" : "directional") + " light";
    }
  }
  if (points != 1) return d.name + " lights with one point light: the scene has " + std::to_string(points);
  if (ambient && !bound("ambient") && !bound("ambient_luma"))
    return d.name + " binds no ambient light: the scene has one";
  if (scene.shading != ShadingMode::Phong)
    return d.name + " shades per pixel: the scene asks for " + std::string(toString(scene.shading)) + " shading";
  std::vector<const Material*> materials{&scene.material};
  for (const SceneObject& o : scene.objects)
    if (o.material) materials.push_back(&*o.material);
  for (const Material* m : materials) {
    const nlohmann::json model = modelJson(*m);
    if (model["type"] != d.model["type"])
      return d.name + " implements the " + d.model["type"].get<std::string>() + " model: the scene's material is " +
             model["type"].get<std::string>();
    for (const auto& [k, v] : d.model.items()) {
      if (!model.contains(k))
        return d.name + ": its model's parameter \"" + k + "\" is not one of the " +
               model["type"].get<std::string>() + " model's";
      if (model[k] != v)
        return d.name + " hard-codes " + k + " = " + v.dump() + ": the scene's material has " + model[k].dump();
    }
    if (m->texture && d.samplers.empty()) return d.name + " reads no texture: the scene's material has one";
    if (!m->texture && !d.samplers.empty())
      return d.name + " reads its colour from a texture: the scene's material has none";
    if (m->texture)
      for (const SamplerBinding& s : d.samplers)
        if (s.filter != "scene" && s.filter != toString(m->texture->filter))
          return d.name + "'s sampler " + s.glsl_name + " filters " + s.filter + ": the scene's texture is " +
                 toString(m->texture->filter) + " (\"texture_filter\": \"scene\" in " + d.file.string() +
                 " takes the scene's)";
    if (!m->texture && m->base_color != dvec3(1.0) && !bound("base_color"))
      return d.name + " binds no base colour: the scene's material is not white";
  }
  // Last: a scene of another model or material says so first.
  if (d.normalize_normal && *d.normalize_normal != scene.normalize_normal)
    return d.name +
           (*d.normalize_normal ? " re-normalises the interpolated normal"
                                : " uses the interpolated normal as it is, not re-normalised") +
           " (\"normalize_normal\": " + (*d.normalize_normal ? "true" : "false") + " in " + d.file.filename().string() +
           "): the scene asks for normalize_normal " + (scene.normalize_normal ? "true" : "false");
  return "";
}

}  // namespace xval::shaderfile
