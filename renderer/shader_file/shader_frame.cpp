#include "shader_file/shader_frame.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "camera/camera.h"
#include "common/export_common.h"
#include "common/supersample.h"
#include "geometry/mesh.h"
#include "geometry/model_textures.h"
#include "geometry/scene_meshes.h"
#include "gl/egl_context.h"
#include "gl/gl_common.h"
#include "shading/lights.h"
#include "shading/models.h"
#include "texture/texture.h"

namespace xval::gl {

namespace {

using shaderfile::QuantityType;

struct Vertex {
  float position[3], normal[3], uv[2];
};

// A 4 x 4 matrix, m[r][c], column-vector maths (clip = m * p).
using Mat4 = std::array<std::array<double, 4>, 4>;

Mat4 identity() {
  Mat4 m{};
  for (int k = 0; k < 4; ++k) m[k][k] = 1;
  return m;
}

Mat4 times(const Mat4& a, const Mat4& b) {
  Mat4 m{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k) m[r][c] += a[r][k] * b[k][c];
  return m;
}

// An active uniform of the program and where its value goes.
struct UniformSlot {
  std::string name, quantity;
  GLint block = -1, offset = 0, matrix_stride = 0, location = -1;
  bool row_major = false;
};

struct Block {
  GLuint buffer = 0;
  std::vector<unsigned char> data;
};

}  // namespace

struct ShaderScene::Impl {
  Scene scene;  // the draws' materials point into it
  std::optional<EglContext> context;
  GLuint program = 0, vao = 0, vbo = 0;
  FrameTargets targets;
  std::vector<GLuint> textures, samplers;
  std::vector<Block> blocks;
  std::vector<UniformSlot> uniforms;
  struct Draw {
    GLint first = 0;
    GLsizei count = 0;
    const Material* material = nullptr;
    GLuint texture = 0;
  };
  std::vector<Draw> draws;
  std::vector<std::string> sampler_filters;  // per sampler unit
  int width = 0, height = 0;
  double setup_seconds = 0.0;
  // Scene-wide values.
  Mat4 view{}, projection{};
  glm::dvec3 eye{0}, light_position{0}, light_color{1}, ambient{0};

  ~Impl() {
    if (!context) return;
    deleteFrameTargets(targets);
    if (!textures.empty()) glDeleteTextures(GLsizei(textures.size()), textures.data());
    if (!samplers.empty()) glDeleteSamplers(GLsizei(samplers.size()), samplers.data());
    for (Block& b : blocks) glDeleteBuffers(1, &b.buffer);
    glDeleteBuffers(1, &vbo);
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(program);
  }

  // The quantity's value for a draw of `m`: 1, 3 or 16 numbers (a matrix row by row).
  std::vector<double> value(const std::string& q, const Material& m) const {
    auto flat = [](const Mat4& x) {
      std::vector<double> v;
      for (const auto& row : x) v.insert(v.end(), row.begin(), row.end());
      return v;
    };
    auto v3 = [](glm::dvec3 v) { return std::vector<double>{v.x, v.y, v.z}; };
    if (q == "world" || q == "world_inverse_transpose") return flat(identity());
    if (q == "view") return flat(view);
    if (q == "projection") return flat(projection);
    if (q == "view_projection" || q == "world_view_projection") return flat(times(projection, view));
    if (q == "camera_position") return v3(eye);
    if (q == "light_position") return v3(light_position);
    if (q == "light_color") return v3(light_color);
    if (q == "ambient") return v3(ambient);
    if (q == "ambient_luma") return {double(models::lightLuma(glm::vec3(ambient)))};
    if (q == "base_color") return v3(m.base_color);
    return {shaderfile::modelParameter(m, q)};  // shininess, ka, kd, ks, luma_offset
  }

  void setUniforms(const Material& m) {
    for (const UniformSlot& u : uniforms) {
      const std::vector<double> v = value(u.quantity, m);
      if (u.block >= 0) {
        Block& b = blocks[size_t(u.block)];
        auto put = [&](size_t at, double x) {
          const float f = float(x);
          if (at + sizeof f > b.data.size())
            throw std::runtime_error("OpenGL: the uniform " + u.name + " lies outside its block");
          std::memcpy(&b.data[at], &f, sizeof f);
        };
        if (v.size() == 16) {
          for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
              put(size_t(u.offset) + size_t(u.row_major ? r * u.matrix_stride + c * 4 : c * u.matrix_stride + r * 4),
                  v[size_t(r * 4 + c)]);
        } else {
          for (size_t k = 0; k < v.size(); ++k) put(size_t(u.offset) + 4 * k, v[k]);
        }
      } else {
        float f[16];
        for (size_t k = 0; k < v.size(); ++k) f[k] = float(v[k]);
        if (v.size() == 16) glProgramUniformMatrix4fv(program, u.location, 1, GL_TRUE, f);  // rows as written
        else if (v.size() == 3) glProgramUniform3fv(program, u.location, 1, f);
        else glProgramUniform1f(program, u.location, f[0]);
      }
    }
    for (Block& b : blocks) glNamedBufferSubData(b.buffer, 0, GLsizeiptr(b.data.size()), b.data.data());
  }
};

namespace {

// The base name of an introspected resource: "_Global.World" -> "World", "a[0]" -> "a".
std::string baseName(std::string n) {
  if (const size_t dot = n.rfind('.'); dot != std::string::npos) n = n.substr(dot + 1);
  if (const size_t br = n.find('['); br != std::string::npos) n = n.substr(0, br);
  return n;
}

std::string resourceName(GLuint p, GLenum iface, GLuint k) {
  char name[256] = {};
  glGetProgramResourceName(p, iface, k, sizeof name, nullptr, name);
  return name;
}

bool typeFits(GLint type, QuantityType q) {
  switch (q) {
    case QuantityType::Float: return type == GL_FLOAT;
    case QuantityType::Vec3: return type == GL_FLOAT_VEC3;
    case QuantityType::Mat4: return type == GL_FLOAT_MAT4;
    case QuantityType::Sampler: return type == GL_SAMPLER_2D;
  }
  return false;
}

const char* typeName(QuantityType q) {
  switch (q) {
    case QuantityType::Float: return "float";
    case QuantityType::Vec3: return "float3 / vec3";
    case QuantityType::Mat4: return "float4x4 / mat4";
    case QuantityType::Sampler: return "sampler2D";
  }
  return "?";
}

}  // namespace

ShaderScene::ShaderScene(const Scene& input, const shaderfile::ShaderDefinition& def, const ShaderProgramText& text)
    : impl_(new Impl) {
  const auto t0 = std::chrono::steady_clock::now();
  Impl& d = *impl_;
  d.scene = resolveModelTextures(input);
  const Scene& scene = d.scene;
  const SubpixelGrid grid = subpixelGrid(scene);
  d.width = grid.width, d.height = grid.height;
  d.context.emplace();

  // The program.
  d.program = buildProgram(text.vertex.c_str(), "compiled vertex stage (GLSL 4.50)", text.fragment.c_str(), "compiled fragment stage (GLSL 4.50)");

  // Geometry, world space, one draw per run of meshes of one material.
  const CameraRays cam(scene.camera);
  std::vector<Vertex> vertices;
  const SceneMeshes sm = sceneMeshes(scene);
  const MaterialSlots slots = materialSlots(scene);
  const SceneDraws geometry =
      walkSceneTriangles(sm, slots, cam, [&](size_t mi, size_t, uint32_t i, glm::dvec2 uv) {
        const TriangleMesh& m = sm.meshes[mi];
        Vertex v{};
        for (int c = 0; c < 3; ++c) v.position[c] = float(m.positions[i][c]), v.normal[c] = float(m.normals[i][c]);
        v.uv[0] = float(uv.x), v.uv[1] = float(uv.y);
        vertices.push_back(v);
      });
  std::vector<size_t> draw_slot;
  for (const DrawRun& run : geometry.runs) {
    d.draws.push_back({run.first, run.count, slots.materials[run.slot], 0});
    draw_slot.push_back(run.slot);
  }
  const double near = geometry.near;
  const double far = std::max(2.0 * geometry.max_depth, 4.0 * near);

  glCreateVertexArrays(1, &d.vao);
  glCreateBuffers(1, &d.vbo);
  glNamedBufferStorage(d.vbo, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.empty() ? nullptr : vertices.data(), 0);
  glVertexArrayVertexBuffer(d.vao, 0, d.vbo, 0, sizeof(Vertex));
  GLint inputs = 0;
  glGetProgramInterfaceiv(d.program, GL_PROGRAM_INPUT, GL_ACTIVE_RESOURCES, &inputs);
  for (GLint k = 0; k < inputs; ++k) {
    const std::string name = resourceName(d.program, GL_PROGRAM_INPUT, GLuint(k));
    const GLenum props[] = {GL_LOCATION};
    GLint location = -1;
    glGetProgramResourceiv(d.program, GL_PROGRAM_INPUT, GLuint(k), 1, props, 1, nullptr, &location);
    if (location < 0) continue;  // a built-in (gl_VertexID)
    const auto it = def.attribute_input.find(name);
    if (it == def.attribute_input.end())
      throw std::runtime_error("the compiled vertex stage's input \"" + name + "\" is bound by nothing (the vertex "
                               "entry " + def.vertex_entry + " names no such input with POSITION, NORMAL or TEXCOORD0)");
    const size_t offset = it->second == "position" ? offsetof(Vertex, position)
                          : it->second == "normal" ? offsetof(Vertex, normal)
                                                   : offsetof(Vertex, uv);
    glEnableVertexArrayAttrib(d.vao, GLuint(location));
    glVertexArrayAttribFormat(d.vao, GLuint(location), it->second == "uv" ? 2 : 3, GL_FLOAT, GL_FALSE, GLuint(offset));
    glVertexArrayAttribBinding(d.vao, GLuint(location), 0);
  }
  checkGl("uploading the vertices");

  // Scene-wide quantities.
  d.eye = cam.origin;
  d.view = Mat4{{{cam.right.x, cam.right.y, cam.right.z, -glm::dot(cam.right, cam.origin)},
                 {cam.up.x, cam.up.y, cam.up.z, -glm::dot(cam.up, cam.origin)},
                 {cam.forward.x, cam.forward.y, cam.forward.z, -glm::dot(cam.forward, cam.origin)},
                 {0, 0, 0, 1}}};
  const double a = far / (far - near);
  d.projection = Mat4{{{1.0 / (cam.tan_half_fov * cam.aspect), 0, 0, 0},
                       {0, 1.0 / cam.tan_half_fov, 0, 0},
                       {0, 0, a, -a * near},
                       {0, 0, 1, 0}}};
  for (const Light& l : scene.lights) {
    if (const auto* p = std::get_if<PointLight>(&l)) d.light_position = p->position, d.light_color = p->color;
    if (const auto* am = std::get_if<AmbientLight>(&l)) d.ambient += am->color;
  }

  // Uniforms and their blocks.
  GLint blocks = 0;
  glGetProgramInterfaceiv(d.program, GL_UNIFORM_BLOCK, GL_ACTIVE_RESOURCES, &blocks);
  for (GLint k = 0; k < blocks; ++k) {
    const GLenum props[] = {GL_BUFFER_DATA_SIZE};
    GLint size = 0;
    glGetProgramResourceiv(d.program, GL_UNIFORM_BLOCK, GLuint(k), 1, props, 1, nullptr, &size);
    Block b;
    b.data.assign(size_t(size), 0);
    glCreateBuffers(1, &b.buffer);
    glNamedBufferStorage(b.buffer, size, nullptr, GL_DYNAMIC_STORAGE_BIT);
    glUniformBlockBinding(d.program, GLuint(k), GLuint(k));
    glBindBufferBase(GL_UNIFORM_BUFFER, GLuint(k), b.buffer);
    d.blocks.push_back(std::move(b));
  }
  GLint uniforms = 0;
  glGetProgramInterfaceiv(d.program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &uniforms);
  for (GLint k = 0; k < uniforms; ++k) {
    const GLenum props[] = {GL_TYPE, GL_BLOCK_INDEX, GL_OFFSET, GL_MATRIX_STRIDE, GL_IS_ROW_MAJOR, GL_LOCATION};
    GLint v[6] = {};
    glGetProgramResourceiv(d.program, GL_UNIFORM, GLuint(k), 6, props, 6, nullptr, v);
    const std::string name = baseName(resourceName(d.program, GL_UNIFORM, GLuint(k)));
    if (v[0] == GL_SAMPLER_2D) {
      const auto s = std::find_if(def.samplers.begin(), def.samplers.end(),
                                  [&](const shaderfile::SamplerBinding& b) { return b.glsl_name == name; });
      if (s == def.samplers.end())
        throw std::runtime_error("the compiled shader's sampler \"" + name + "\" is bound by nothing (no sampler "
                                 "of the effect reads a DIFFUSE texture under that name)");
      glProgramUniform1i(d.program, v[5], GLint(d.sampler_filters.size()));
      d.sampler_filters.push_back(s->filter);
      continue;
    }
    const auto q = def.uniform_quantity.find(name);
    if (q == def.uniform_quantity.end())
      throw std::runtime_error("the compiled shader's uniform \"" + name + "\" is bound by nothing: no semantic "
                               "xval knows and no entry in \"uniforms\" of " + def.file.string());
    const shaderfile::Quantity* quantity = shaderfile::findQuantity(q->second);
    if (!typeFits(v[0], quantity->type))
      throw std::runtime_error("the uniform \"" + name + "\" is bound to " + q->second + ", a " +
                               typeName(quantity->type) + ", but its compiled type is GL type " + std::to_string(v[0]));
    d.uniforms.push_back({name, q->second, v[1], v[2], v[3], v[5], v[4] != 0});
  }
  checkGl("introspecting the uniforms");

  // Textures (one per material slot that has one) and one sampler object per unit.
  std::vector<GLuint> slot_texture(slots.materials.size(), 0);
  for (size_t k = 0; k < slots.materials.size(); ++k)
    if (slots.used[k] && slots.materials[k]->texture && !d.sampler_filters.empty()) {
      slot_texture[k] = uploadTextureRgba32f(*slots.materials[k]->texture, true);
      d.textures.push_back(slot_texture[k]);
    }
  for (size_t i = 0; i < d.draws.size(); ++i) d.draws[i].texture = slot_texture[draw_slot[i]];
  for (size_t u = 0; u < d.sampler_filters.size(); ++u) {
    GLuint s = 0;
    glCreateSamplers(1, &s);
    d.samplers.push_back(s);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glSamplerParameterf(s, GL_TEXTURE_MAX_ANISOTROPY, 1.0f);
  }

  d.targets = makeFrameTargets(d.width, d.height);

  glUseProgram(d.program);
  setDrawState(def.pipeline.depth_less_equal ? GL_LEQUAL : GL_LESS, d.targets, d.width, d.height, d.vao);
  checkGl("setting the state");
  d.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

ShaderScene::~ShaderScene() = default;

void ShaderScene::draw() {
  Impl& d = *impl_;
  const float clear_colour[4] = {0, 0, 0, 0};
  const float clear_depth = 1.0f;
  glClearNamedFramebufferfv(d.targets.fbo, GL_COLOR, 0, clear_colour);
  glClearNamedFramebufferfv(d.targets.fbo, GL_DEPTH, 0, &clear_depth);
  for (const Impl::Draw& dr : d.draws) {
    if (dr.count == 0) continue;
    d.setUniforms(*dr.material);
    for (size_t u = 0; u < d.sampler_filters.size(); ++u) {
      std::string f = d.sampler_filters[u];
      if (f == "scene" && dr.material->texture) f = toString(dr.material->texture->filter);
      const GLuint s = d.samplers[u];
      glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER,
                          f == "trilinear" ? GL_LINEAR_MIPMAP_LINEAR : f == "nearest" ? GL_NEAREST : GL_LINEAR);
      glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, f == "nearest" ? GL_NEAREST : GL_LINEAR);
      glBindSampler(GLuint(u), s);
      glBindTextureUnit(GLuint(u), dr.texture);
    }
    glDrawArrays(GL_TRIANGLES, dr.first, dr.count);
  }
  glFinish();
  checkGl("drawing the frame");
}

Image ShaderScene::drawAndRead() {
  draw();
  const Impl& d = *impl_;
  Image img = readColourTopDown(d.targets, d.width, d.height);
  const std::vector<float> depth = readDepthTopDown(d.targets, d.width, d.height);
  for (size_t i = 0; i < depth.size(); ++i) {  // the hit mask: a depth was written
    const bool hit = depth[i] < 1.0f;
    for (int c = 0; c < 3; ++c) img.rgba[i * 4 + c] = hit ? img.rgba[i * 4 + c] : 0.0f;
    img.rgba[i * 4 + 3] = hit ? 1.0f : 0.0f;
  }
  return img;
}

std::string ShaderScene::device() const { return impl_->context->describe(); }
double ShaderScene::setupSeconds() const { return impl_->setup_seconds; }

Image renderWithShader(const Scene& scene, const shaderfile::ShaderDefinition& def, const ShaderProgramText& program) {
  const SubpixelGrid g = subpixelGrid(scene);
  ShaderScene s(scene, def, program);
  return finishFrame(s.drawAndRead(), g.n, def.name);
}

}  // namespace xval::gl
