#include "gl/gl_common.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "common/export_common.h"
#include "common/supersample.h"
#include "geometry/mesh.h"
#include "texture/texture.h"

namespace xval::gl {

SceneDraws walkSceneTriangles(const SceneMeshes& sm, const MaterialSlots& slots, const CameraRays& cam,
                              const std::function<void(size_t, size_t, uint32_t, glm::dvec2)>& corner) {
  SceneDraws out;
  double min_depth = std::numeric_limits<double>::infinity();
  int corners = 0;
  for (size_t mi = 0; mi < sm.meshes.size(); ++mi) {
    const TriangleMesh& m = sm.meshes[mi];
    const size_t slot = slots.object_slot[sm.object[mi]];
    if (out.runs.empty() || out.runs.back().slot != slot) out.runs.push_back({slot, corners, 0});
    for (size_t t = 0; t < m.triangles.size(); ++t) {
      const glm::dvec2 uv0 = m.uvs[m.triangles[t][0]];
      for (int k = 0; k < 3; ++k) {
        const uint32_t i = m.triangles[t][k];
        corner(mi, t, i, (uv0 - glm::floor(uv0)) + (m.uvs[i] - uv0));
        const double z = glm::dot(m.positions[i] - cam.origin, cam.forward);
        min_depth = std::min(min_depth, z);
        out.max_depth = std::max(out.max_depth, z);
        ++corners;
      }
    }
    out.runs.back().count = corners - out.runs.back().first;
  }
  out.near = !(min_depth > 0.0) ? std::max(out.max_depth, 1.0) * 1e-6 : 0.5 * min_depth;
  return out;
}

void checkGl(const char* what) {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%04x", unsigned(e));
    throw std::runtime_error(std::string("OpenGL: ") + what + " failed (GL error " + buf + ")");
  }
}

GlName compileStage(unsigned int stage, const char* source, const std::string& name) {
  const GLuint s = glCreateShader(stage);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    glDeleteShader(s);
    throw std::runtime_error("OpenGL: the " + name + " does not compile: " + log);
  }
  return s;
}

GlName buildProgram(const char* vertex, const std::string& vertex_name, const char* fragment,
                    const std::string& fragment_name) {
  const GLuint vs = compileStage(GL_VERTEX_SHADER, vertex, vertex_name);
  GLuint fs = 0;
  try {
    fs = compileStage(GL_FRAGMENT_SHADER, fragment, fragment_name);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  glDeleteShader(vs);
  glDeleteShader(fs);
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

void checkTextureSize(int width, int height) {
  GLint max_tex = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_tex);
  if (width > max_tex || height > max_tex)
    throw std::runtime_error("OpenGL: a " + std::to_string(width) + " x " + std::to_string(height) +
                             " texture exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(max_tex));
}

GlName uploadTextureRgba32f(const TextureSpec& spec, bool mip_chain) {
  const Texture tex = loadTexture(spec);
  std::vector<float> rgba(size_t(tex.width) * tex.height * 4, 1.0f);
  for (int y = 0; y < tex.height; ++y)
    for (int x = 0; x < tex.width; ++x) {
      const glm::vec3 c = tex.texel(x, y);
      float* o = &rgba[(size_t(y) * tex.width + x) * 4];
      o[0] = c.x, o[1] = c.y, o[2] = c.z;
    }
  checkTextureSize(tex.width, tex.height);
  GLsizei levels = 1;  // a chain: every level down to 1 x 1, floor(log2(max)) + 1
  while (mip_chain && std::max(tex.width, tex.height) >> levels) ++levels;
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, levels, GL_RGBA32F, tex.width, tex.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(t, 0, 0, 0, tex.width, tex.height, GL_RGBA, GL_FLOAT, rgba.data());
  if (mip_chain) glGenerateTextureMipmap(t);
  return t;
}

FrameTargets makeFrameTargets(int width, int height) {
  GLint max_rb = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_rb);
  if (width > max_rb || height > max_rb)
    throw std::runtime_error("OpenGL: a " + std::to_string(width) + " x " + std::to_string(height) +
                             " frame exceeds GL_MAX_RENDERBUFFER_SIZE " + std::to_string(max_rb));
  FrameTargets t;
  glCreateRenderbuffers(1, &t.colour);
  glNamedRenderbufferStorage(t.colour, GL_RGBA32F, width, height);
  glCreateRenderbuffers(1, &t.depth);
  glNamedRenderbufferStorage(t.depth, GL_DEPTH_COMPONENT32F, width, height);
  glCreateFramebuffers(1, &t.fbo);
  glNamedFramebufferRenderbuffer(t.fbo, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.colour);
  glNamedFramebufferRenderbuffer(t.fbo, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth);
  const GLenum status = glCheckNamedFramebufferStatus(t.fbo, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("OpenGL: the RGBA32F + DEPTH32F framebuffer is incomplete (status " +
                             std::to_string(status) + ")");
  checkGl("making the framebuffer");
  return t;
}

void deleteFrameTargets(FrameTargets& t) {
  glDeleteFramebuffers(1, &t.fbo);
  glDeleteRenderbuffers(1, &t.colour);
  glDeleteRenderbuffers(1, &t.depth);
  t = {};
}

void setDrawState(unsigned int depth_func, const FrameTargets& t, int width, int height, GlName vao) {
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(depth_func);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_MULTISAMPLE);
  glDisable(GL_DITHER);
  glViewport(0, 0, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
  glBindVertexArray(vao);
}

Image readColourTopDown(const FrameTargets& t, int width, int height) {
  std::vector<float> rows(size_t(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glNamedFramebufferReadBuffer(t.fbo, GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, t.fbo);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rows.data());
  checkGl("reading the frame back");
  Image img(width, height, false);
  const size_t row = size_t(width) * 4;
  for (int y = 0; y < height; ++y)  // GL's row 0 is the bottom
    std::copy_n(&rows[size_t(height - 1 - y) * row], row, &img.rgba[size_t(y) * row]);
  return img;
}

std::vector<float> readDepthTopDown(const FrameTargets& t, int width, int height) {
  std::vector<float> rows(size_t(width) * height), out(rows.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, t.fbo);
  glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, rows.data());
  checkGl("reading the depth back");
  for (int y = 0; y < height; ++y)
    std::copy_n(&rows[size_t(height - 1 - y) * width], width, &out[size_t(y) * width]);
  return out;
}

Image finishFrame(Image fine, int n, const std::string& renderer) {
  requireFinite(renderer, fine);
  fine.raw.resize(size_t(fine.width) * fine.height * 3);
  for (size_t i = 0; i < size_t(fine.width) * fine.height; ++i)
    for (int c = 0; c < 3; ++c) fine.raw[i * 3 + c] = fine.rgba[i * 4 + c];
  return boxFilter(fine, n);
}

}  // namespace xval::gl
