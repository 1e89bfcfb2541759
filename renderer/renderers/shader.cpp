// A user's shader as a renderer (docs/shaders.md): a definition file of
// format "xval-shader/1" given to --renderer-file (renderers/
// renderer_file.h reads the format and hands it here), its effect prepared
// and its uniforms bound when the file is read (shader_file/
// shader_definition.h), compiled to GLSL 4.50 by glslangValidator and
// spirv-cross (shader_file/shader_compile.h, once per process), drawn on
// the gl renderer's context (gl/shader_frame.h).
//
// The draw runs in a forked child (process/run_process.h runForked) with
// the render's time-out: a shader that never finishes (an infinite loop;
// llvmpipe has no watchdog) is killed and the render fails "timed out",
// as does an outside tool; a crash in the driver costs that render only.
// bench: one such forked render first (so a frame is known to end), then
// frames in this process.
//
// Scenes the shader cannot express (shaderCannotExpress: not one point
// light, another model or hard-coded parameter, a texture filter the
// sampler does not apply, ...) are refused with the reason before anything
// runs. Version: glslangValidator's. Precision: gl's (float32 on the same
// driver).
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>

#include "common/export_common.h"
#include "files/scratch_folder.h"
#include "gl/egl_context.h"
#include "gl/shader_frame.h"
#include "process/run_process.h"
#include "renderers/renderer.h"
#include "renderers/renderer_file.h"
#include "shader_file/shader_compile.h"

namespace xval::renderers {

namespace {

using shaderfile::ShaderDefinition;
using shaderfile::ShaderProgramText;

// The compiled program, made once per process for a definition.
struct CompiledOnce {
  std::mutex lock;
  std::optional<ShaderProgramText> program;
  std::string error;  // a failed compile's message, repeated to later renders
};

const ShaderProgramText& compiled(const ShaderDefinition& d, CompiledOnce& once) {
  std::lock_guard<std::mutex> g(once.lock);
  if (once.program) return *once.program;
  if (!once.error.empty()) throw ExternalToolError(once.error);
  try {
    const ScratchFolder scratch("shader");
    once.program = shaderfile::compileShader(d, scratch.dir());
  } catch (const std::exception& e) {
    once.error = e.what();
    throw ExternalToolError(once.error);
  }
  return *once.program;
}

// An image as bytes and back (the forked draw's result).
std::string imageBytes(const Image& img) {
  std::string out(2 * sizeof(int), '\0');
  std::memcpy(&out[0], &img.width, sizeof(int));
  std::memcpy(&out[sizeof(int)], &img.height, sizeof(int));
  out.append(reinterpret_cast<const char*>(img.rgba.data()), img.rgba.size() * sizeof(float));
  out.append(reinterpret_cast<const char*>(img.raw.data()), img.raw.size() * sizeof(float));
  return out;
}

Image imageFromBytes(const std::string& bytes, int w, int h) {
  const size_t pixels = size_t(w) * h, expected = 2 * sizeof(int) + pixels * 7 * sizeof(float);
  int got_w = 0, got_h = 0;
  if (bytes.size() == expected) {
    std::memcpy(&got_w, &bytes[0], sizeof(int));
    std::memcpy(&got_h, &bytes[sizeof(int)], sizeof(int));
  }
  if (got_w != w || got_h != h)
    throw ExternalToolError("the forked draw returned " + std::to_string(bytes.size()) + " bytes, expected a " +
                            std::to_string(w) + " x " + std::to_string(h) + " image (" + std::to_string(expected) + ")");
  Image img(w, h, true);
  std::memcpy(img.rgba.data(), &bytes[2 * sizeof(int)], pixels * 4 * sizeof(float));
  std::memcpy(img.raw.data(), &bytes[2 * sizeof(int) + pixels * 4 * sizeof(float)], pixels * 3 * sizeof(float));
  return img;
}

Image renderForked(const ShaderDefinition& d, const ShaderProgramText& program, const Scene& scene,
                   double timeout_seconds) {
  const int w = scene.camera.width, h = scene.camera.height;
  const ForkedResult f = runForked(
      [&] {
        try {
          return imageBytes(gl::renderWithShader(scene, d, program));
        } catch (const gl::GlUnavailable& e) {
          throw std::runtime_error(std::string("gl: unavailable: ") + e.what());
        }
      },
      timeout_seconds, 2 * sizeof(int) + size_t(w) * h * 7 * sizeof(float) + 1);
  if (!f.process.ok())
    throw ExternalToolError(d.name + ": the draw (" + d.source.string() + " on OpenGL) " + f.process.describe() +
                            (f.process.timed_out ? " (a shader that does not finish: llvmpipe has no watchdog, xval "
                                                   "kills the draw at the render's time-out, --timeout)"
                                                 : "") +
                            (f.summary().empty() ? "" : ": " + f.summary()));
  return imageFromBytes(f.output, w, h);
}

}  // namespace

Renderer shaderFileRenderer(const std::filesystem::path& file, const nlohmann::json& doc) {
  auto def = std::make_shared<const ShaderDefinition>(shaderfile::loadShaderDefinition(file, doc));
  auto once = std::make_shared<CompiledOnce>();
  Renderer r;
  r.id = def->name;
  r.display_name = def->name;
  std::string edits;
  for (const shaderfile::SourceEdit& e : def->effect.edits)
    edits += (edits.empty() ? "" : "; ") + std::string("line ") + std::to_string(e.line) + ": " + e.what;
  r.summary = (def->description.empty() ? "" : def->description + "; ") + "the " + def->language + " shader " +
              def->source.string() + " (defined by " + def->file.string() + ") on OpenGL" +
              (edits.empty() ? "" : "; the tool's edits: " + edits);
  r.version_command = {shaderfile::kGlslangTool, "--version"};
  r.version_marker = "Glslang Version";
  r.definition_file = def->file;
  r.missing = [] { return shaderfile::compilersMissing(); };
  r.cannot_express = [def](const Scene& scene) { return shaderfile::shaderCannotExpress(*def, scene); };
  r.render = [def, once](const Scene& scene, const RenderRequest& request, RenderInfo* info) {
    if (const std::string why = shaderfile::shaderCannotExpress(*def, scene); !why.empty()) throw ExportError(why);
    const auto t0 = std::chrono::steady_clock::now();
    Image img = renderForked(*def, compiled(*def, *once), scene, request.timeout_seconds);
    if (info) info->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return img;
  };
  r.prepare_frames = [def, once](const Scene& scene) {
    if (const std::string why = shaderfile::shaderCannotExpress(*def, scene); !why.empty()) throw ExportError(why);
    const ShaderProgramText& program = compiled(*def, *once);
    renderForked(*def, program, scene, kDefaultToolTimeoutSeconds);  // a frame ends before one is timed here
    std::shared_ptr<gl::ShaderScene> prepared;
    try {
      prepared = std::make_shared<gl::ShaderScene>(scene, *def, program);
    } catch (const gl::GlUnavailable& e) {
      throw ExternalToolError(def->name + ": gl: unavailable: " + e.what());
    }
    return FrameLoop{[prepared] { prepared->draw(); }, prepared->device(), prepared->setupSeconds()};
  };
  return r;
}

}  // namespace xval::renderers
