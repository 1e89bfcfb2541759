#include "gl/gl_frame.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

#include "camera/camera.h"
#include "common/export_common.h"
#include "common/supersample.h"
#include "geometry/front_faces.h"
#include "geometry/mesh.h"
#include "geometry/model_textures.h"
#include "geometry/scene_meshes.h"
#include "gl/egl_context.h"
#include "gl/gl_common.h"
#include "gl/glsl_models.h"
#include "shading/flat_normals.h"
#include "shading/lights.h"
#include "shading/models.h"
#include "texture/texture.h"

namespace xval::gl {

namespace {

// One vertex of the unindexed triangle list (glsl_models.h's attributes).
struct Vertex {
  float position[3], normal[3], uv[2], face_normal[3];
};

void put(float* out, glm::dvec3 v) { out[0] = float(v.x), out[1] = float(v.y), out[2] = float(v.z); }

// The light as the shaders' std140 uniform block (glsl_models.cpp, struct Light).
struct LightBlock {
  float position_kind[4], direction_cos[4], colour_luma[4], attenuation[4];
};

LightBlock lightBlock(const PreparedLight<float>& l) {
  return {{l.position.x, l.position.y, l.position.z, 0.f},
          {l.direction.x, l.direction.y, l.direction.z, l.cos_cutoff},
          {l.color.x, l.color.y, l.color.z, l.color_luma},
          {l.att_c, l.att_l, l.att_q, 0.f}};
}

// The light's kind as the shaders' k_light_kind (glsl_models.cpp).
int lightKind(const PreparedLight<float>& l) {
  using K = PreparedLight<float>::Kind;
  return l.kind == K::Point ? 0 : l.kind == K::Directional ? 1 : 2;
}

// The model's numbers as the shaders' uniforms (its switches are the
// program's ShaderVariant).
struct ModelUniforms {
  float ka = 1, kd = 1, ks = 1, n = 55, offset = 0.1f, factor = 0;
  glm::vec3 c0{1}, c1{0}, c2{0};
  float on_a = 1, on_b = 0;  // oren_nayar: A, B (models::orenNayar*AB)
  float ct_alpha = 0.25f, ct_f0 = 0.04f;  // cook_torrance
};

// The model's uniforms, and its switches into `v` (k_model is the
// registry's id: glsl_models.cpp's MODEL_<NAME> constants).
ModelUniforms modelUniforms(const LightingModel& m, ShaderVariant& v) {
  ModelUniforms u;
  v.model = modelId(m);
  std::visit(model::Overloaded{
                 [&u, &v](const ClassicPhong& mm) {
                   v.course = mm.variant == ClassicPhong::Variant::Course;
                   u.ka = float(mm.ka), u.kd = float(mm.kd), u.ks = float(mm.ks), u.n = float(mm.shininess);
                   v.specular = mm.ks != 0.0;
                 },
                 [&u, &v](const YiqLuma& mm) {
                   u.kd = float(mm.kd), u.ks = float(mm.ks), u.n = float(mm.shininess);
                   u.offset = float(mm.luma_offset), v.specular = mm.ks != 0.0;
                 },
                 [&u](const Lambert& mm) { u.c0 = glm::vec3(mm.c0); },
                 [&u](const WrapAround& mm) { u.c0 = glm::vec3(mm.c0), u.factor = float(mm.factor); },
                 [&u](const Hemispherical& mm) { u.c0 = glm::vec3(mm.c0), u.c2 = glm::vec3(mm.c2); },
                 [&u](const BiDirectional& mm) { u.c0 = glm::vec3(mm.c0), u.c2 = glm::vec3(mm.c2); },
                 [&u](const Trilight& mm) {
                   u.c0 = glm::vec3(mm.c0), u.c1 = glm::vec3(mm.c1), u.c2 = glm::vec3(mm.c2);
                 },
                 // minnaert, blinn_phong, oren_nayar
                 [&u](const Minnaert& mm) { u.kd = float(mm.kd), u.n = float(mm.k); },
                 [&u, &v](const BlinnPhong& mm) {
                   u.ka = float(mm.ka), u.kd = float(mm.kd), u.ks = float(mm.ks), u.n = float(mm.shininess);
                   v.specular = mm.ks != 0.0;
                 },
                 [&u, &v](const OrenNayar& mm) {
                   u.kd = float(mm.kd), v.on_cycles = mm.variant == OrenNayar::Variant::Cycles;
                   const models::OrenNayarAB ab = v.on_cycles ? models::orenNayarCyclesAB(mm.sigma)
                                                              : models::orenNayarQualitativeAB(mm.sigma);
                   u.on_a = float(ab.a), u.on_b = float(ab.b);
                 },
                 [&u, &v](const CookTorrance& mm) {
                   u.kd = float(mm.kd), u.ks = float(mm.ks), v.specular = mm.ks != 0.0;
                   v.ct_distribution = int(mm.distribution), v.ct_geometry = int(mm.geometry);
                   v.ct_fresnel = int(mm.fresnel), u.ct_alpha = float(mm.roughness), u.ct_f0 = float(mm.f0);
                 }},
             m);
  return u;
}

// Uploads `spec` as an RGBA32F texture of one level (appended to `owned`,
// which deletes it); returns it and the shaders' k_texture mode (1 nearest, 3 trilinear,
// 2 bilinear).
std::pair<GLuint, int> uploadTexture(const TextureSpec& spec, std::vector<GLuint>& owned) {
  // Trilinear: every level down to 1 x 1, made by the driver.
  const bool trilinear = spec.filter == TextureFilter::Trilinear;
  const GLuint t = uploadTextureRgba32f(spec, trilinear);
  owned.push_back(t);
  if (trilinear) {
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTextureParameterf(t, GL_TEXTURE_MAX_ANISOTROPY, 1.0f);
  } else {
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  checkGl("uploading the texture");
  return {t, trilinear ? 3 : spec.filter == TextureFilter::Nearest ? 1 : 2};
}

// Whether this driver's GLSL decodes every 8-bit code c to c / 255 in float
// exactly (glsl_models.h codeValueCheckSource; GLSL allows a division 2.5
// ULP of error, llvmpipe's is IEEE's): run once, read back, compared.
bool codeValuesExact() {
  const GLuint cs = compileStage(GL_COMPUTE_SHADER, codeValueCheckSource().c_str(), "code value check");
  const GLuint p = glCreateProgram();
  glAttachShader(p, cs);
  glLinkProgram(p);
  glDeleteShader(cs);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    glDeleteProgram(p);
    throw std::runtime_error("OpenGL: the code value check does not link");
  }
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, 256 * sizeof(float), nullptr, 0);
  glUseProgram(p);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  float v[256] = {};
  glGetNamedBufferSubData(buffer, 0, sizeof v, v);
  glDeleteBuffers(1, &buffer);
  glDeleteProgram(p);
  checkGl("checking the shaders' code values");
  for (int c = 0; c < 256; ++c)
    if (v[c] != float(c) / 255.0f) return false;
  return true;
}

// `tex`'s 8-bit codes (Texture::packed) as an RGBA8UI texture of one level,
// row 0 the image's top, alpha 0 (unread).
GLuint uploadTextureCodes(const Texture& tex) {
  std::vector<unsigned char> codes(tex.packed.size() * 4, 0);
  for (size_t i = 0; i < tex.packed.size(); ++i)
    for (int c = 0; c < 3; ++c) codes[4 * i + size_t(c)] = (unsigned char)((tex.packed[i] >> (8 * c)) & 255u);
  checkTextureSize(tex.width, tex.height);
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, GL_RGBA8UI, tex.width, tex.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(t, 0, 0, 0, tex.width, tex.height, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, codes.data());
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  checkGl("uploading the texture's codes");
  return t;
}

}  // namespace

// One draw call: a run of vertices of one material, its uniforms and texture.
struct Draw {
  GLint first = 0;
  GLsizei count = 0;
  ModelUniforms model;
  glm::vec3 base{1};
  // Its program's switches: ShaderVariant::texture 0 none, 1 nearest,
  // 2 bilinear, 3 trilinear; ShaderVariant::luma_only (colour/luma_only.h)
  // 0 off, else 1 + LumaSpace, also the draw's light set (the lights, or
  // their greys in that space).
  ShaderVariant variant;
  size_t program = 0;  // GlScene::Impl::programs
  // Its uniforms are set in each frame: its program also draws others.
  bool uniforms_per_frame = false;
  GLuint texture = 0;
  // Back faces culled: every object of the draw passes
  // objectBackFacesNeverFirstHit (geometry/front_faces.h).
  bool cull_back_faces = false;
};

// Per light: whether the shaders' towardsLight can take its rescaling path
// on a triangle of `dr` (shading/lights.h towardsLightMayRescale of each
// triangle's box; a directional light never calls it).
std::vector<bool> lightsMayRescale(const std::vector<Vertex>& vertices, const Draw& dr, const std::vector<int>& kinds,
                                   const std::vector<glm::dvec3>& positions) {
  std::vector<bool> may(kinds.size(), false);
  for (GLint t = dr.first; t + 2 < dr.first + dr.count; t += 3) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (GLint k = t; k < t + 3; ++k) {
      const float* p = vertices[size_t(k)].position;
      lo = glm::min(lo, glm::dvec3(p[0], p[1], p[2])), hi = glm::max(hi, glm::dvec3(p[0], p[1], p[2]));
    }
    for (size_t i = 0; i < kinds.size(); ++i)
      if (kinds[i] != 1 && !may[i]) may[i] = towardsLightMayRescale(positions[i], lo, hi);
  }
  return may;
}

// One set of lights as the shaders read them: the buffer and the ambient.
struct LightSet {
  GLuint buffer = 0;  // the shaders' uniform block Lights
  glm::vec3 ambient{0};
};

// The draw's material and ambient light as the shaders' uniforms (the
// program in use; a uniform the program does not read is at location -1,
// which glUniform ignores).
void setMaterialUniforms(GLuint p, const Draw& d, const LightSet& ls) {
  auto loc = [p](const char* name) { return glGetUniformLocation(p, name); };
  const ModelUniforms& mu = d.model;
  glUniform1f(loc("u_ka"), mu.ka);
  glUniform1f(loc("u_kd"), mu.kd);
  glUniform1f(loc("u_ks"), mu.ks);
  glUniform1f(loc("u_n"), mu.n);
  glUniform1f(loc("u_offset"), mu.offset);
  glUniform1f(loc("u_factor"), mu.factor);
  glUniform3f(loc("u_c0"), mu.c0.x, mu.c0.y, mu.c0.z);
  glUniform3f(loc("u_c1"), mu.c1.x, mu.c1.y, mu.c1.z);
  glUniform3f(loc("u_c2"), mu.c2.x, mu.c2.y, mu.c2.z);
  glUniform1f(loc("u_on_a"), mu.on_a);
  glUniform1f(loc("u_on_b"), mu.on_b);
  glUniform3f(loc("u_base"), d.base.x, d.base.y, d.base.z);
  glUniform1f(loc("u_ct_alpha"), mu.ct_alpha);
  glUniform1f(loc("u_ct_f0"), mu.ct_f0);
  glUniform3f(loc("u_ambient"), ls.ambient.x, ls.ambient.y, ls.ambient.z);
  glUniform1f(loc("u_ambient_luma"), models::lightLuma(ls.ambient));
}

struct GlScene::Impl {
  std::optional<EglContext> context;
  std::vector<GLuint> programs;  // one per distinct ShaderVariant of the draws
  GLuint vao = 0, vbo = 0;
  // By Draw::luma_only: the scene's lights, their greys in yiq, in cie_lstar.
  std::array<LightSet, 1 + kLumaSpaceNames.size()> light_sets;
  FrameTargets targets;
  std::vector<GLuint> textures;
  std::vector<Draw> draws;
  int width = 0, height = 0;
  double setup_seconds = 0.0;

  ~Impl() {
    if (!context) return;
    deleteFrameTargets(targets);
    if (!textures.empty()) glDeleteTextures(GLsizei(textures.size()), textures.data());
    for (const LightSet& l : light_sets) glDeleteBuffers(1, &l.buffer);
    glDeleteBuffers(1, &vbo);
    glDeleteVertexArrays(1, &vao);
    for (GLuint p : programs) glDeleteProgram(p);
  }
};

GlScene::GlScene(const Scene& input) : impl_(new Impl) {
  // Texture source "model": one object, so one draw and texture, per
  // primitive (geometry/model_textures.h).
  const Scene scene = resolveModelTextures(input);
  const auto t0 = std::chrono::steady_clock::now();
  Impl& d = *impl_;
  const SubpixelGrid grid = subpixelGrid(scene);  // checked before anything is allocated
  d.width = grid.width, d.height = grid.height;
  d.context.emplace();

  // Geometry: camera-relative, unindexed.
  const CameraRays cam(scene.camera);
  std::vector<Vertex> vertices;
  // The meshes in order, one draw per run of meshes of one material slot.
  const SceneMeshes sm = sceneMeshes(scene);
  const MaterialSlots slots = materialSlots(scene);
  std::vector<std::vector<glm::dvec3>> faces(sm.meshes.size());  // flat shading's, per mesh
  if (scene.shading == ShadingMode::Flat)
    for (size_t mi = 0; mi < sm.meshes.size(); ++mi) faces[mi] = flatNormals(sm.meshes[mi]);
  const SceneDraws geometry =
      walkSceneTriangles(sm, slots, cam, [&](size_t mi, size_t t, uint32_t i, glm::dvec2 uv) {
        const TriangleMesh& m = sm.meshes[mi];
        Vertex v{};
        put(v.position, m.positions[i] - cam.origin);
        put(v.normal, m.normals[i]);
        v.uv[0] = float(uv.x), v.uv[1] = float(uv.y);
        if (!faces[mi].empty()) put(v.face_normal, faces[mi][t]);
        vertices.push_back(v);
      });
  // Draws: the runs of one material slot, split where the meshes' back-face
  // rule changes (geometry/front_faces.h: a closed, untransformed knot or
  // sphere seen from outside never shows a back face first, so culling
  // them only skips fragments that a front face covers).
  std::vector<size_t> draw_slot;
  {
    std::vector<GLint> mesh_first(sm.meshes.size() + 1, 0);  // each mesh's corners, in walk order
    for (size_t mi = 0; mi < sm.meshes.size(); ++mi)
      mesh_first[mi + 1] = mesh_first[mi] + GLint(3 * sm.meshes[mi].triangles.size());
    size_t mi = 0;
    for (const DrawRun& run : geometry.runs) {
      for (; mi < sm.meshes.size() && mesh_first[mi] < run.first + run.count; ++mi) {
        if (mesh_first[mi + 1] == mesh_first[mi]) continue;  // no triangles
        const bool cull = objectBackFacesNeverFirstHit(scene.objects[sm.object[mi]], sm.meshes[mi], cam.origin);
        Draw* last = d.draws.empty() ? nullptr : &d.draws.back();
        if (last && draw_slot.back() == run.slot && last->cull_back_faces == cull &&
            last->first + last->count == mesh_first[mi]) {
          last->count += mesh_first[mi + 1] - mesh_first[mi];
          continue;
        }
        d.draws.push_back(Draw{});
        d.draws.back().first = mesh_first[mi], d.draws.back().count = mesh_first[mi + 1] - mesh_first[mi];
        d.draws.back().cull_back_faces = cull;
        draw_slot.push_back(run.slot);
      }
    }
  }
  const double near = geometry.near;

  glCreateVertexArrays(1, &d.vao);
  glCreateBuffers(1, &d.vbo);
  glNamedBufferStorage(d.vbo, GLsizeiptr(vertices.size() * sizeof(Vertex)),
                       vertices.empty() ? nullptr : vertices.data(), 0);
  glVertexArrayVertexBuffer(d.vao, 0, d.vbo, 0, sizeof(Vertex));
  const struct {
    int location, size;
    size_t offset;
  } attribs[] = {{kAttribPosition, 3, offsetof(Vertex, position)},
                 {kAttribNormal, 3, offsetof(Vertex, normal)},
                 {kAttribUv, 2, offsetof(Vertex, uv)},
                 {kAttribFaceNormal, 3, offsetof(Vertex, face_normal)}};
  for (const auto& a : attribs) {
    glEnableVertexArrayAttrib(d.vao, a.location);
    glVertexArrayAttribFormat(d.vao, a.location, a.size, GL_FLOAT, GL_FALSE, GLuint(a.offset));
    glVertexArrayAttribBinding(d.vao, a.location, 0);
  }
  checkGl("uploading the vertices");

  // Lights, relative to the eye (shading/lights.h prepareLights): the
  // scene's, and for the luma-only mode their greys in each luma space
  // (greyLights), so that every model's GLSL reads the lights it is given.
  // The sets differ in colour only: one list of kinds for the programs.
  std::vector<int> light_kinds;
  std::vector<bool> light_attenuated;
  std::vector<glm::dvec3> light_positions;  // relative to the eye, as the shaders read them
  for (size_t set = 0; set < d.light_sets.size(); ++set) {
    std::vector<PreparedLight<float>> lights;
    prepareLights<float>(set == 0 ? scene.lights : greyLights(scene.lights, LumaSpace(set - 1)),
                         d.light_sets[set].ambient, lights, cam.origin);
    std::vector<int> kinds;
    std::vector<bool> attenuated;
    std::vector<LightBlock> blocks;
    for (const auto& l : lights) {
      blocks.push_back(lightBlock(l));
      kinds.push_back(lightKind(l));
      attenuated.push_back(l.has_attenuation);
    }
    if (set == 0) {
      light_kinds = kinds, light_attenuated = attenuated;
      for (const auto& l : lights) light_positions.push_back(glm::dvec3(l.position));
    }
    else if (kinds != light_kinds || attenuated != light_attenuated)
      throw std::logic_error("gl: the grey lights of luma space " + std::string(kLumaSpaceNames[set - 1]) +
                             " differ from the scene's lights in kind or attenuation");
    if (blocks.empty()) blocks.push_back(LightBlock{});  // a buffer may not be empty; k_light_count says 0
    GLint max_block = 0;  // the uniform block's limit (at least 16 KB: 256 lights)
    glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &max_block);
    if (blocks.size() * sizeof(LightBlock) > size_t(max_block))
      throw std::runtime_error("OpenGL: " + std::to_string(blocks.size()) + " lights take " +
                               std::to_string(blocks.size() * sizeof(LightBlock)) +
                               " bytes, more than this driver's uniform block of " + std::to_string(max_block));
    glCreateBuffers(1, &d.light_sets[set].buffer);
    glNamedBufferStorage(d.light_sets[set].buffer, GLsizeiptr(blocks.size() * sizeof(LightBlock)), blocks.data(), 0);
  }
  checkGl("uploading the lights");

  // Per material slot: its uniforms and texture (RGBA32F, one level, read
  // by texelFetch only), uploaded once and shared by its draws.
  // Nearest and bilinear read the 8-bit codes where they give the same
  // values (ShaderVariant::texture_codes).
  std::vector<int> slot_texture_mode(slots.materials.size(), 0);
  std::vector<GLuint> slot_texture(slots.materials.size(), 0);
  std::vector<bool> slot_texture_codes(slots.materials.size(), false);
  std::optional<bool> codes_exact;  // codeValuesExact, asked once when needed
  for (size_t k = 0; k < slots.materials.size(); ++k) {
    if (!slots.used[k] || !slots.materials[k]->texture) continue;
    const TextureSpec& spec = *slots.materials[k]->texture;
    if (spec.filter != TextureFilter::Trilinear) {
      const Texture tex = loadTexture(spec);
      if (!tex.packed.empty() && tex.codes_are_c_over_255 && !codes_exact) codes_exact = codeValuesExact();
      if (!tex.packed.empty() && tex.codes_are_c_over_255 && *codes_exact) {
        slot_texture[k] = uploadTextureCodes(tex);
        d.textures.push_back(slot_texture[k]);
        slot_texture_mode[k] = spec.filter == TextureFilter::Nearest ? 1 : 2;
        slot_texture_codes[k] = true;
        continue;
      }
    }
    std::tie(slot_texture[k], slot_texture_mode[k]) = uploadTexture(spec, d.textures);
  }

  // Per draw: its uniforms and its program, one per distinct variant.
  std::vector<ShaderVariant> variants;
  std::vector<int> draws_of_program;
  for (size_t i = 0; i < d.draws.size(); ++i) {
    Draw& dr = d.draws[i];
    const Material& mat = *slots.materials[draw_slot[i]];
    ShaderVariant& v = dr.variant;
    dr.model = modelUniforms(mat.model, v);
    dr.base = glm::vec3(mat.base_color);
    dr.texture = slot_texture[draw_slot[i]];
    v.shading = scene.shading == ShadingMode::Flat ? 0 : scene.shading == ShadingMode::Gouraud ? 1 : 2;
    v.normalize_normal = scene.normalize_normal;
    v.texture = slot_texture_mode[draw_slot[i]];
    v.texture_codes = slot_texture_codes[draw_slot[i]];
    v.luma_only = mat.luma_only ? 1 + int(*mat.luma_only) : 0;
    v.light_kinds = light_kinds, v.light_attenuated = light_attenuated;
    v.light_may_rescale = lightsMayRescale(vertices, dr, light_kinds, light_positions);
    dr.program = size_t(std::find(variants.begin(), variants.end(), v) - variants.begin());
    if (dr.program == variants.size()) {
      variants.push_back(v);
      draws_of_program.push_back(0);
      d.programs.push_back(buildProgram(vertexShaderSource(v).c_str(), "vertex shader",
                                        fragmentShaderSource(v).c_str(), "fragment shader"));
    }
    ++draws_of_program[dr.program];
  }

  // Targets.
  d.targets = makeFrameTargets(d.width, d.height);

  // Uniforms: the camera's in every program; a draw's own once here when
  // its program draws nothing else, else in each frame.
  const float view[9] = {float(cam.right.x),   float(cam.right.y),   float(cam.right.z),
                         float(cam.up.x),      float(cam.up.y),      float(cam.up.z),
                         float(cam.forward.x), float(cam.forward.y), float(cam.forward.z)};
  for (GLuint p : d.programs) {
    glUseProgram(p);
    auto loc = [p](const char* name) { return glGetUniformLocation(p, name); };
    glUniformMatrix3fv(loc("u_view"), 1, GL_TRUE, view);  // rows as written
    glUniform2f(loc("u_scale"), float(1.0 / (cam.tan_half_fov * cam.aspect)), float(1.0 / cam.tan_half_fov));
    glUniform1f(loc("u_near"), float(near));
  }
  for (Draw& dr : d.draws) {
    dr.uniforms_per_frame = draws_of_program[dr.program] > 1;
    if (dr.uniforms_per_frame) continue;
    glUseProgram(d.programs[dr.program]);
    setMaterialUniforms(d.programs[dr.program], dr, d.light_sets[size_t(dr.variant.luma_only)]);
  }
  checkGl("setting the uniforms");

  // Fixed state: reversed Z, the whole frame, no blending; culling per draw.
  setDrawState(GL_GREATER, d.targets, d.width, d.height, d.vao);
  checkGl("setting the state");
  d.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

GlScene::~GlScene() = default;

void GlScene::draw() {
  const Impl& d = *impl_;
  const float clear_colour[4] = {0, 0, 0, 0};
  const float clear_depth = 0.0f;  // reversed Z: 0 is infinitely far
  glClearNamedFramebufferfv(d.targets.fbo, GL_COLOR, 0, clear_colour);
  glClearNamedFramebufferfv(d.targets.fbo, GL_DEPTH, 0, &clear_depth);
  for (const Draw& dr : d.draws) {
    if (dr.count == 0) continue;
    const GLuint p = d.programs[dr.program];
    const LightSet& ls = d.light_sets[size_t(dr.variant.luma_only)];
    glUseProgram(p);
    if (dr.uniforms_per_frame) setMaterialUniforms(p, dr, ls);
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightsBinding, ls.buffer);
    if (dr.texture) glBindTextureUnit(dr.variant.texture_codes ? kCodesUnit : kTextureUnit, dr.texture);
    if (dr.cull_back_faces)
      glEnable(GL_CULL_FACE);  // GL_BACK of GL_CCW: the mesh's winding normal faces the eye when counter-clockwise
    else
      glDisable(GL_CULL_FACE);
    glDrawArrays(GL_TRIANGLES, dr.first, dr.count);
  }
  glFinish();
  checkGl("drawing the frame");
}

Image GlScene::drawAndRead() {
  draw();
  return readColourTopDown(impl_->targets, impl_->width, impl_->height);
}

std::string GlScene::device() const { return impl_->context->describe(); }
double GlScene::setupSeconds() const { return impl_->setup_seconds; }

Image renderWithGl(const std::string& renderer, const Scene& scene, std::string* device) {
  const SubpixelGrid g = subpixelGrid(scene);
  GlScene gl(scene);
  if (device) *device = gl.device();
  return finishFrame(gl.drawAndRead(), g.n, renderer);
}

}  // namespace xval::gl
