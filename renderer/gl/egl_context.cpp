#include "gl/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <cstdio>
#include <cstring>
#include <mutex>

namespace xval::gl {

namespace {

std::string eglError(const char* what) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s failed (EGL error 0x%04x)", what, unsigned(eglGetError()));
  return buf;
}

// The surfaceless display, initialised once; throws GlUnavailable.
EGLDisplay surfacelessDisplay() {
  static std::mutex lock;
  static EGLDisplay display = EGL_NO_DISPLAY;
  static std::string failure;
  std::lock_guard<std::mutex> g(lock);
  if (display != EGL_NO_DISPLAY) return display;
  if (!failure.empty()) throw GlUnavailable(failure);
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!client || !std::strstr(client, "EGL_MESA_platform_surfaceless")) {
    const std::string listed = !client ? eglError("eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)")
                               : *client ? std::string(client)
                                         : std::string("none: no EGL vendor library was loaded");
    failure = "EGL: no surfaceless platform (EGL_MESA_platform_surfaceless) among the client extensions (" +
              listed + ")";
    throw GlUnavailable(failure);
  }
  auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_display) {
    failure = "EGL: eglGetPlatformDisplayEXT not found";
    throw GlUnavailable(failure);
  }
  EGLDisplay d = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (d == EGL_NO_DISPLAY) {
    failure = "EGL: " + eglError("eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)");
    throw GlUnavailable(failure);
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(d, &major, &minor)) {
    failure = "EGL: " + eglError("eglInitialize on the surfaceless platform");
    throw GlUnavailable(failure);
  }
  display = d;
  return display;
}

}  // namespace

EglContext::EglContext() {
  EGLDisplay d = surfacelessDisplay();
  const char* ext = eglQueryString(d, EGL_EXTENSIONS);
  if (!ext || !std::strstr(ext, "EGL_KHR_no_config_context") || !std::strstr(ext, "EGL_KHR_surfaceless_context"))
    throw GlUnavailable(std::string("EGL: the display lacks EGL_KHR_no_config_context or "
                                    "EGL_KHR_surfaceless_context: ") +
                        (ext ? ext : "no extension string"));
  if (!eglBindAPI(EGL_OPENGL_API)) throw GlUnavailable("EGL: " + eglError("eglBindAPI(EGL_OPENGL_API)"));
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext c = eglCreateContext(d, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (c == EGL_NO_CONTEXT) throw GlUnavailable("EGL: " + eglError("eglCreateContext (OpenGL 4.5 core)"));
  if (!eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, c)) {
    const std::string e = eglError("eglMakeCurrent (surfaceless)");
    eglDestroyContext(d, c);
    throw GlUnavailable("EGL: " + e);
  }
  display_ = d;
  context_ = c;
}

EglContext::~EglContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglReleaseThread();
}

std::string EglContext::describe() const {
  auto s = [](GLenum e) {
    const GLubyte* v = glGetString(e);
    return v ? std::string(reinterpret_cast<const char*>(v)) : std::string("?");
  };
  return s(GL_RENDERER) + ", " + s(GL_VERSION);
}

std::string glUnavailableReason() {
  try {
    EglContext probe;
  } catch (const GlUnavailable& e) {
    return e.what();
  }
  return "";
}

}  // namespace xval::gl
