// An OpenGL 4.5 core context without a window: EGL's surfaceless platform
// (EGL_MESA_platform_surfaceless; Mesa's llvmpipe on a machine without a
// GPU, the vendor's driver where there is one), no config, no surface. The
// context renders only into framebuffer objects.
//
//   EglContext ctx;            // throws GlUnavailable with the reason
//   ... GL calls on this thread ...
//
// The context is current on the constructing thread until destroyed. The
// EGL display is initialised once per process and never terminated (other
// threads may hold contexts on it).
#pragma once

#include <stdexcept>
#include <string>

namespace xval::gl {

// No OpenGL 4.5 core context could be made: what failed and EGL's error.
struct GlUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class EglContext {
 public:
  EglContext();  // throws GlUnavailable
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
  std::string describe() const;

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
};

// Why no context can be made here ("" when one can): creates one and drops it.
std::string glUnavailableReason();

}  // namespace xval::gl
