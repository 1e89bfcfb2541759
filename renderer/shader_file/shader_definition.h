// A user's shader as a renderer: its definition file (format
// "xval-shader/1", docs/shaders.md), read and checked, with the effect
// prepared (shader_file/effect_source.h) and every uniform's binding
// decided, before anything renders.
//
//   {"format": "xval-shader/1",
//    "name": "paper-listing",                 // its renderer id, as a renderer file's name
//    "source": "kotsarenko2012_table1.fx",    // beside this file, inside its folder
//    "language": "hlsl",
//    "vertex_entry": "PhongVertexShader", "fragment_entry": "LumaDiffusePS",
//    "model": {"type": "yiq_luma", "kd": 1, "ks": 1, "luma_offset": 0.1},
//    "uniforms": {"AmbientValue": "ambient_luma"},   // optional: uniform -> scene quantity
//    "texture_filter": "scene",               // optional: "effect" (default) or "scene"
//    "normalize_normal": false,               // optional: the shader re-normalises the interpolated normal or not
//    "timeout_s": 60}                         // optional: each compiler run's time-out
//
// "language": "glsl" (any #version the OpenGL 4.5 core context compiles):
// "source" is the fragment stage and "vertex_source" the vertex stage,
// both entries "main", every uniform bound by "uniforms" (a sampler by
// "diffuse_texture", read with the scene's filter) and the vertex inputs
// by "attributes": {"a_position": "position", "a_normal": "normal",
// "a_uv": "uv"}.
//
// A uniform is bound by its semantic (kSemantics below, case-insensitive,
// as FX Composer binds them) or by "uniforms"; one bound by neither is an
// error naming it and its line, never a silent zero. "model" is the
// lighting model the shader implements: its scene-file type and the value
// of each parameter the shader hard-codes; a scene of another model or
// another value of a listed parameter is refused (not expressible).
// "normalize_normal", when given, is what the shader's pixel stage does with
// the interpolated normal (the scene field of that name, docs/scene-format.md):
// a scene asking for the other is refused, as for a model parameter; absent,
// the shader is compared on both and the difference shows.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "shader_file/effect_source.h"

namespace xval::shaderfile {

inline constexpr const char* kShaderFileFormat = "xval-shader/1";
// A shader source larger than this is refused (a shader is a few KiB).
inline constexpr std::uintmax_t kMaxShaderSourceBytes = 1 << 20;
// Each compiler run's default time-out, seconds.
inline constexpr double kDefaultCompileTimeoutSeconds = 60.0;

// What a scene supplies to a shader: its name in "uniforms" and the GLSL
// type it must have.
enum class QuantityType { Float, Vec3, Mat4, Sampler };
struct Quantity {
  const char* name;
  QuantityType type;
  const char* meaning;
};
inline constexpr Quantity kQuantities[] = {
    {"world", QuantityType::Mat4, "object to world: the identity (the meshes are in world space)"},
    {"world_inverse_transpose", QuantityType::Mat4, "the normals' matrix: the identity"},
    {"view", QuantityType::Mat4, "world to camera (x right, y up, z forward)"},
    {"projection", QuantityType::Mat4, "camera to clip (depth 0 at the near plane, 1 at the far one)"},
    {"view_projection", QuantityType::Mat4, "world to clip"},
    {"world_view_projection", QuantityType::Mat4, "object to clip"},
    {"camera_position", QuantityType::Vec3, "the eye, world space"},
    {"light_position", QuantityType::Vec3, "the scene's one point light, world space"},
    {"light_color", QuantityType::Vec3, "that light's colour"},
    {"ambient", QuantityType::Vec3, "the sum of the scene's ambient lights"},
    {"ambient_luma", QuantityType::Float, "its luma (YIQ Y), as the YIQ model's A"},
    {"base_color", QuantityType::Vec3, "the material's base colour"},
    {"shininess", QuantityType::Float, "the model's exponent n"},
    {"ka", QuantityType::Float, "the model's ka"},
    {"kd", QuantityType::Float, "the model's kd"},
    {"ks", QuantityType::Float, "the model's ks"},
    {"luma_offset", QuantityType::Float, "the YIQ model's luma offset"},
    {"diffuse_texture", QuantityType::Sampler, "the material's texture"},
};
const Quantity* findQuantity(const std::string& name);

// FX Composer semantics xval binds (upper-cased) -> quantity.
inline constexpr std::pair<const char*, const char*> kSemantics[] = {
    {"WORLD", "world"},
    {"WORLDINVERSETRANSPOSE", "world_inverse_transpose"},
    {"VIEW", "view"},
    {"PROJECTION", "projection"},
    {"VIEWPROJECTION", "view_projection"},
    {"WORLDVIEWPROJECTION", "world_view_projection"},
    {"CAMERAPOSITION", "camera_position"},
    {"POSITION", "light_position"},  // a light's position (FX Composer: Object = "PointLight0")
    {"SPECULARPOWER", "shininess"},
    {"DIFFUSE", "diffuse_texture"},  // on a texture: its samplers read the material's texture
};

// The vertex inputs a scene supplies, by semantic (upper-cased, index 0 implied).
inline constexpr std::pair<const char*, const char*> kVertexSemantics[] = {
    {"POSITION", "position"}, {"POSITION0", "position"}, {"NORMAL", "normal"},
    {"NORMAL0", "normal"},    {"TEXCOORD", "uv"},        {"TEXCOORD0", "uv"},
};

// The host's pipeline state, from the effect's pass (or its defaults).
struct PipelineState {
  bool depth_less_equal = true;  // ZFunc LessEqual (else Less)
};

// How a sampler is set: its filter ("scene": the scene's), repeat addressing.
struct SamplerBinding {
  std::string glsl_name;  // as the compiled GLSL names it
  std::string filter;     // "nearest", "bilinear", "trilinear" or "scene"
};

struct ShaderDefinition {
  std::string name, description;
  std::filesystem::path file;    // the definition, absolute
  std::filesystem::path source;  // the shader source (GLSL: the fragment stage), absolute, inside file's folder
  std::filesystem::path vertex_source;  // GLSL: the vertex stage (HLSL: empty, `source` holds both)
  std::string language;          // "hlsl" or "glsl"
  std::string vertex_entry, fragment_entry;
  nlohmann::json model;  // {"type": ..., hard-coded parameters}
  std::optional<bool> normalize_normal;  // the shader's own normal handling, when declared
  double timeout_s = kDefaultCompileTimeoutSeconds;
  PreparedEffect effect;  // HLSL only
  PipelineState pipeline;
  std::map<std::string, std::string> uniform_quantity;    // uniform -> quantity
  std::map<std::string, std::string> attribute_input;     // GLSL vertex input -> position|normal|uv
  std::vector<SamplerBinding> samplers;
};

// Reads and checks the definition and its source. Throws SceneError naming
// the file, the field and the value (or the source's line).
ShaderDefinition loadShaderDefinition(const std::filesystem::path& file, const nlohmann::json& doc);

// Why the shader cannot render `scene` as the scene describes it ("" when
// it can): the lights (one point light, white and unattenuated unless a
// uniform takes its colour; ambient only when a uniform takes it), every
// material's model against "model", the textures against the samplers,
// shading phong, the scene's normalize_normal against a declared one.
std::string shaderCannotExpress(const ShaderDefinition& d, const Scene& scene);

// The value of a model parameter ("shininess") of `material`, as the
// scene file writes it; throws std::runtime_error when the model has none.
double modelParameter(const Material& material, const std::string& key);

}  // namespace xval::shaderfile
