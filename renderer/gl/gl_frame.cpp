#include "gl/gl_frame.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <algorithm>
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
#include "geometry/mesh.h"
#include "geometry/model_textures.h"
#include "geometry/scene_meshes.h"
#include "gl/egl_context.h"
#include "gl/glsl_models.h"
#include "shading/flat_normals.h"
#include "shading/lights.h"
#include "shading/models.h"
#include "texture/texture.h"

namespace xval::gl {

namespace {

void checkGl(const char* what) {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%04x", unsigned(e));
    throw std::runtime_error(std::string("OpenGL: ") + what + " failed (GL error " + buf + ")");
  }
}

GLuint compile(GLenum stage, const char* source, const char* name) {
  const GLuint s = glCreateShader(stage);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    glDeleteShader(s);
    throw std::runtime_error(std::string("OpenGL: the ") + name + " shader does not compile: " + log);
  }
  return s;
}

GLuint link(GLuint vs, GLuint fs) {
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetProgramInfoLog(p, sizeof log, nullptr, log);
    glDeleteProgram(p);
    throw std::runtime_error(std::string("OpenGL: the shader program does not link: ") + log);
  }
  return p;
}

// One vertex of the unindexed triangle list (glsl_models.h's attributes).
struct Vertex {
  float position[3], normal[3], uv[2], face_normal[3];
};

void put(float* out, glm::dvec3 v) { out[0] = float(v.x), out[1] = float(v.y), out[2] = float(v.z); }

// The light as the shaders' std430 block (glsl_models.cpp, struct Light).
struct LightBlock {
  float position_kind[4], direction_cos[4], colour_luma[4], attenuation[4];
};

LightBlock lightBlock(const PreparedLight<float>& l) {
  using K = PreparedLight<float>::Kind;
  const float kind = l.kind == K::Point ? 0.f : l.kind == K::Directional ? 1.f : 2.f;
  return {{l.position.x, l.position.y, l.position.z, kind},
          {l.direction.x, l.direction.y, l.direction.z, l.cos_cutoff},
          {l.color.x, l.color.y, l.color.z, l.color_luma},
          {l.att_c, l.att_l, l.att_q, l.has_attenuation ? 1.f : 0.f}};
}

// The model's parameters as the shaders' uniforms.
struct ModelUniforms {
  int model = 0;
  bool course = false, specular = false;
  float ka = 1, kd = 1, ks = 1, n = 55, offset = 0.1f, factor = 0;
  glm::vec3 c0{1}, c1{0}, c2{0};
};

// u_model is the registry's id (glsl_models.cpp's MODEL_<NAME> constants).
ModelUniforms modelUniforms(const LightingModel& m) {
  ModelUniforms u;
  u.model = int(modelId(m));
  std::visit(model::Overloaded{
                 [&u](const ClassicPhong& mm) {
                   u.course = mm.variant == ClassicPhong::Variant::Course;
                   u.ka = float(mm.ka), u.kd = float(mm.kd), u.ks = float(mm.ks), u.n = float(mm.shininess);
                   u.specular = mm.ks != 0.0;
                 },
                 [&u](const YiqLuma& mm) {
                   u.kd = float(mm.kd), u.ks = float(mm.ks), u.n = float(mm.shininess);
                   u.offset = float(mm.luma_offset), u.specular = mm.ks != 0.0;
                 },
                 [&u](const Lambert& mm) { u.c0 = glm::vec3(mm.c0); },
                 [&u](const WrapAround& mm) { u.c0 = glm::vec3(mm.c0), u.factor = float(mm.factor); },
                 [&u](const Hemispherical& mm) { u.c0 = glm::vec3(mm.c0), u.c2 = glm::vec3(mm.c2); },
                 [&u](const BiDirectional& mm) { u.c0 = glm::vec3(mm.c0), u.c2 = glm::vec3(mm.c2); },
                 [&u](const Trilight& mm) {
                   u.c0 = glm::vec3(mm.c0), u.c1 = glm::vec3(mm.c1), u.c2 = glm::vec3(mm.c2);
                 }},
             m);
  return u;
}

// Uploads `spec` as an RGBA32F texture of one level (appended to `owned`,
// which deletes it); returns it and the shaders' u_texture mode (1 nearest, 3 trilinear,
// 2 bilinear).
std::pair<GLuint, int> uploadTexture(const TextureSpec& spec, std::vector<GLuint>& owned) {
  const Texture tex = loadTexture(spec);
  std::vector<float> rgba(size_t(tex.width) * tex.height * 4, 1.0f);
  for (int y = 0; y < tex.height; ++y)
    for (int x = 0; x < tex.width; ++x) {
      const glm::vec3 c = tex.texel(x, y);
      float* o = &rgba[(size_t(y) * tex.width + x) * 4];
      o[0] = c.x, o[1] = c.y, o[2] = c.z;
    }
  GLint max_tex = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_tex);
  if (tex.width > max_tex || tex.height > max_tex)
    throw std::runtime_error("OpenGL: a " + std::to_string(tex.width) + " x " + std::to_string(tex.height) +
                             " texture exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(max_tex));
  // Trilinear: every level down to 1 x 1, made by the driver.
  const bool trilinear = spec.filter == TextureFilter::Trilinear;
  GLsizei levels = 1;
  while (trilinear && std::max(tex.width, tex.height) >> levels) ++levels;  // floor(log2(max)) + 1
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  owned.push_back(t);
  glTextureStorage2D(t, levels, GL_RGBA32F, tex.width, tex.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(t, 0, 0, 0, tex.width, tex.height, GL_RGBA, GL_FLOAT, rgba.data());
  if (trilinear) {
    glGenerateTextureMipmap(t);
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

}  // namespace

// One draw call: a run of vertices of one material, its uniforms and texture.
struct Draw {
  GLint first = 0;
  GLsizei count = 0;
  ModelUniforms model;
  glm::vec3 base{1};
  int texture_mode = 0;  // 0 none, 1 nearest, 2 bilinear, 3 trilinear
  GLuint texture = 0;
};

// The draw's material as the shaders' uniforms (the program in use).
void setMaterialUniforms(GLuint p, const Draw& d) {
  auto loc = [p](const char* name) { return glGetUniformLocation(p, name); };
  const ModelUniforms& mu = d.model;
  glUniform1i(loc("u_model"), mu.model);
  glUniform1i(loc("u_course"), mu.course);
  glUniform1i(loc("u_specular"), mu.specular);
  glUniform1f(loc("u_ka"), mu.ka);
  glUniform1f(loc("u_kd"), mu.kd);
  glUniform1f(loc("u_ks"), mu.ks);
  glUniform1f(loc("u_n"), mu.n);
  glUniform1f(loc("u_offset"), mu.offset);
  glUniform1f(loc("u_factor"), mu.factor);
  glUniform3f(loc("u_c0"), mu.c0.x, mu.c0.y, mu.c0.z);
  glUniform3f(loc("u_c1"), mu.c1.x, mu.c1.y, mu.c1.z);
  glUniform3f(loc("u_c2"), mu.c2.x, mu.c2.y, mu.c2.z);
  glUniform3f(loc("u_base"), d.base.x, d.base.y, d.base.z);
  glUniform1i(loc("u_texture"), d.texture_mode);
}

struct GlScene::Impl {
  std::optional<EglContext> context;
  GLuint program = 0, vao = 0, vbo = 0, ssbo = 0, fbo = 0, colour_rb = 0, depth_rb = 0;
  std::vector<GLuint> textures;
  std::vector<Draw> draws;
  int width = 0, height = 0;
  double setup_seconds = 0.0;

  ~Impl() {
    if (!context) return;
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &colour_rb);
    glDeleteRenderbuffers(1, &depth_rb);
    if (!textures.empty()) glDeleteTextures(GLsizei(textures.size()), textures.data());
    glDeleteBuffers(1, &ssbo);
    glDeleteBuffers(1, &vbo);
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(program);
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

  GLint max_rb = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_rb);
  if (d.width > max_rb || d.height > max_rb)
    throw std::runtime_error("OpenGL: a " + std::to_string(d.width) + " x " + std::to_string(d.height) +
                             " frame exceeds GL_MAX_RENDERBUFFER_SIZE " + std::to_string(max_rb));

  // Geometry: camera-relative, unindexed.
  const CameraRays cam(scene.camera);
  std::vector<Vertex> vertices;
  double min_depth = std::numeric_limits<double>::infinity(), max_depth = 0.0;
  // The meshes in order, one draw per run of meshes of one material slot.
  const SceneMeshes sm = sceneMeshes(scene);
  const MaterialSlots slots = materialSlots(scene);
  std::vector<size_t> draw_slot;
  for (size_t mi = 0; mi < sm.meshes.size(); ++mi) {
    const TriangleMesh& m = sm.meshes[mi];
    const size_t slot = slots.object_slot[sm.object[mi]];
    if (d.draws.empty() || draw_slot.back() != slot) {
      d.draws.push_back(Draw{});
      d.draws.back().first = GLint(vertices.size());
      draw_slot.push_back(slot);
    }
    const std::vector<glm::dvec3> faces =
        scene.shading == ShadingMode::Flat ? flatNormals(m) : std::vector<glm::dvec3>(m.triangles.size());
    for (size_t t = 0; t < m.triangles.size(); ++t) {
      const glm::dvec2 uv0 = m.uvs[m.triangles[t][0]];
      for (int k = 0; k < 3; ++k) {
        const uint32_t i = m.triangles[t][k];
        Vertex v{};
        const glm::dvec3 p = m.positions[i] - cam.origin;
        put(v.position, p);
        put(v.normal, m.normals[i]);
        const glm::dvec2 uv = (uv0 - glm::floor(uv0)) + (m.uvs[i] - uv0);
        v.uv[0] = float(uv.x), v.uv[1] = float(uv.y);
        put(v.face_normal, faces[t]);
        vertices.push_back(v);
        const double z = glm::dot(p, cam.forward);
        min_depth = std::min(min_depth, z);
        max_depth = std::max(max_depth, z);
      }
    }
    d.draws.back().count = GLsizei(vertices.size()) - d.draws.back().first;
  }
  const double near = !(min_depth > 0.0) ? std::max(max_depth, 1.0) * 1e-6 : 0.5 * min_depth;

  const GLuint vs = compile(GL_VERTEX_SHADER, vertexShaderSource(), "vertex");
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragmentShaderSource(), "fragment");
    d.program = link(vs, fs);
  } catch (...) {
    glDeleteShader(vs);
    if (fs) glDeleteShader(fs);
    throw;
  }
  glDeleteShader(vs);
  glDeleteShader(fs);

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

  // Lights, relative to the eye (shading/lights.h prepareLights).
  glm::vec3 ambient(0);
  std::vector<PreparedLight<float>> lights;
  prepareLights<float>(scene.lights, ambient, lights, cam.origin);
  std::vector<LightBlock> blocks;
  for (const auto& l : lights) blocks.push_back(lightBlock(l));
  if (blocks.empty()) blocks.push_back(LightBlock{});  // a buffer may not be empty; u_light_count says 0
  glCreateBuffers(1, &d.ssbo);
  glNamedBufferStorage(d.ssbo, GLsizeiptr(blocks.size() * sizeof(LightBlock)), blocks.data(), 0);
  checkGl("uploading the lights");

  // Per material slot: its uniforms and texture (RGBA32F, one level, read
  // by texelFetch only), uploaded once and shared by its draws.
  std::vector<int> slot_texture_mode(slots.materials.size(), 0);
  std::vector<GLuint> slot_texture(slots.materials.size(), 0);
  for (size_t k = 0; k < slots.materials.size(); ++k)
    if (slots.used[k] && slots.materials[k]->texture)
      std::tie(slot_texture[k], slot_texture_mode[k]) = uploadTexture(*slots.materials[k]->texture, d.textures);
  for (size_t i = 0; i < d.draws.size(); ++i) {
    const Material& mat = *slots.materials[draw_slot[i]];
    d.draws[i].model = modelUniforms(mat.model);
    d.draws[i].base = glm::vec3(mat.base_color);
    d.draws[i].texture = slot_texture[draw_slot[i]];
    d.draws[i].texture_mode = slot_texture_mode[draw_slot[i]];
  }

  // Targets.
  glCreateRenderbuffers(1, &d.colour_rb);
  glNamedRenderbufferStorage(d.colour_rb, GL_RGBA32F, d.width, d.height);
  glCreateRenderbuffers(1, &d.depth_rb);
  glNamedRenderbufferStorage(d.depth_rb, GL_DEPTH_COMPONENT32F, d.width, d.height);
  glCreateFramebuffers(1, &d.fbo);
  glNamedFramebufferRenderbuffer(d.fbo, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, d.colour_rb);
  glNamedFramebufferRenderbuffer(d.fbo, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, d.depth_rb);
  const GLenum status = glCheckNamedFramebufferStatus(d.fbo, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("OpenGL: the RGBA32F + DEPTH32F framebuffer is incomplete (status " +
                             std::to_string(status) + ")");
  checkGl("making the framebuffer");

  // Uniforms.
  const GLuint p = d.program;
  glUseProgram(p);
  auto loc = [p](const char* name) { return glGetUniformLocation(p, name); };
  const float view[9] = {float(cam.right.x),   float(cam.right.y),   float(cam.right.z),
                         float(cam.up.x),      float(cam.up.y),      float(cam.up.z),
                         float(cam.forward.x), float(cam.forward.y), float(cam.forward.z)};
  glUniformMatrix3fv(loc("u_view"), 1, GL_TRUE, view);  // rows as written
  glUniform2f(loc("u_scale"), float(1.0 / (cam.tan_half_fov * cam.aspect)), float(1.0 / cam.tan_half_fov));
  glUniform1f(loc("u_near"), float(near));
  glUniform1i(loc("u_shading"), scene.shading == ShadingMode::Flat ? 0 : scene.shading == ShadingMode::Gouraud ? 1 : 2);
  glUniform3f(loc("u_ambient"), ambient.x, ambient.y, ambient.z);
  glUniform1f(loc("u_ambient_luma"), models::lightLuma(ambient));
  glUniform1i(loc("u_normalize_normal"), scene.normalize_normal);
  glUniform1i(loc("u_light_count"), GLint(lights.size()));
  checkGl("setting the uniforms");

  // Fixed state: reversed Z, the whole frame, no culling or blending.
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_MULTISAMPLE);
  glDisable(GL_DITHER);
  glViewport(0, 0, d.width, d.height);
  glBindFramebuffer(GL_FRAMEBUFFER, d.fbo);
  glBindVertexArray(d.vao);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightsBinding, d.ssbo);
  checkGl("setting the state");
  d.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

GlScene::~GlScene() = default;

void GlScene::draw() {
  const Impl& d = *impl_;
  const float clear_colour[4] = {0, 0, 0, 0};
  const float clear_depth = 0.0f;  // reversed Z: 0 is infinitely far
  glClearNamedFramebufferfv(d.fbo, GL_COLOR, 0, clear_colour);
  glClearNamedFramebufferfv(d.fbo, GL_DEPTH, 0, &clear_depth);
  for (const Draw& dr : d.draws) {
    if (dr.count == 0) continue;
    setMaterialUniforms(d.program, dr);
    if (dr.texture) glBindTextureUnit(kTextureUnit, dr.texture);
    glDrawArrays(GL_TRIANGLES, dr.first, dr.count);
  }
  glFinish();
  checkGl("drawing the frame");
}

Image GlScene::drawAndRead() {
  draw();
  const Impl& d = *impl_;
  std::vector<float> rows(size_t(d.width) * d.height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glNamedFramebufferReadBuffer(d.fbo, GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, d.width, d.height, GL_RGBA, GL_FLOAT, rows.data());
  checkGl("reading the frame back");
  Image img(d.width, d.height, false);
  const size_t row = size_t(d.width) * 4;
  for (int y = 0; y < d.height; ++y)  // GL's row 0 is the bottom
    std::copy_n(&rows[size_t(d.height - 1 - y) * row], row, &img.rgba[size_t(y) * row]);
  return img;
}

std::string GlScene::device() const { return impl_->context->describe(); }
double GlScene::setupSeconds() const { return impl_->setup_seconds; }

Image renderWithGl(const Scene& scene, std::string* device) {
  const SubpixelGrid g = subpixelGrid(scene);
  GlScene gl(scene);
  if (device) *device = gl.device();
  Image fine = gl.drawAndRead();
  requireFinite("gl", fine);
  fine.raw.resize(size_t(fine.width) * fine.height * 3);
  for (size_t i = 0; i < size_t(fine.width) * fine.height; ++i)
    for (int c = 0; c < 3; ++c) fine.raw[i * 3 + c] = fine.rgba[i * 4 + c];
  return boxFilter(fine, g.n);
}

}  // namespace xval::gl
