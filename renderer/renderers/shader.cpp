// A user's shader as a renderer (docs/shaders.md): a definition file of
// format "xval-shader/1" given to --renderer-file (renderers/
// renderer_file.h reads the format and hands it here), its effect prepared
// and its uniforms bound when the file is read (shader_file/
// shader_definition.h), compiled to GLSL 4.50 by glslangValidator and
// spirv-cross (shader_file/shader_compile.h, once per process), drawn on
// the gl renderer's context (shader_file/shader_frame.h).
//
// The draw runs in a process of its own, xval-shader-draw beside the xval
// executable (shader_file/shader_draw_main.cpp), with the render's
// time-out (process/run_process.h): a shader that does not finish is
// killed and the render fails "timed out", as an outside tool would; a
// crash in the driver costs that render only. (Not a fork of this process:
// an EGL display this process made for gl does not work in a forked child,
// which then hangs.) Its files go to the render's work folder: the scene,
// the GLSL, the log. bench: one such render first (so a frame is known to
// end), then frames in this process.
//
// Scenes the shader cannot express (shaderCannotExpress: not one point
// light, another model or hard-coded parameter, a texture filter the
// sampler does not apply, ...) are refused with the reason before anything
// runs. Version: glslangValidator's. Precision: gl's (float32 on the same
// driver).
#include <chrono>
#include <fstream>
#include <sstream>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>

#include "common/export_common.h"
#include "files/atomic_write.h"
#include "files/scratch_folder.h"
#include "gl/egl_context.h"
#include "shader_file/shader_frame.h"
#include "process/run_process.h"
#include "renderers/renderer.h"
#include "renderers/renderer_file.h"
#include "scene_file/scene_writer.h"
#include "shader_file/shader_compile.h"
#include "shader_file/shader_image_bytes.h"

namespace xval::renderers {

namespace {

using shaderfile::ShaderDefinition;
using shaderfile::ShaderProgramText;

inline constexpr const char* kDrawHelper = "xval-shader-draw";

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

// The helper beside the running executable (xval's build or install folder).
std::filesystem::path drawHelper() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path(kDrawHelper) : self.parent_path() / kDrawHelper;
}

// One frame drawn by xval-shader-draw in `dir`, with the time-out.
Image renderInHelper(const ShaderDefinition& d, const ShaderProgramText& program, const Scene& scene,
                     double timeout_seconds, const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  const fs::path helper = drawHelper();
  if (!fs::is_regular_file(helper))
    throw ExternalToolError(d.name + ": " + helper.string() + " is missing (xval-shader-draw is built beside xval)");
  // The scene as xval resolved it; tolerances and renderers are the caller's business.
  auto json = sceneToJson(scene);
  json.erase("tolerances");
  json.erase("renderers");
  const std::string token = attemptToken();
  const fs::path scene_file = dir / ("scene-" + token + ".json"), vert = dir / "vert.glsl",
                 frag = dir / "frag.glsl", out = dir / ("frame-" + token + ".bin"), log = dir / (d.name + ".log");
  writeFileAtomically(scene_file, json.dump(1) + "\n");
  writeFileAtomically(vert, program.vertex);
  writeFileAtomically(frag, program.fragment);
  const ProcessResult r = runProcess({helper.string(), d.file.string(), scene_file.string(), vert.string(),
                                      frag.string(), out.string()},
                                     dir, log, timeout_seconds);
  if (!r.ok())
    throw ExternalToolError(d.name + ": the draw (" + d.source.string() + " on OpenGL) " + r.describe() +
                            (r.timed_out ? " (a shader that does not finish is killed at the render's time-out, "
                                           "--timeout; llvmpipe ends each loop after 65536 turns but has no "
                                           "watchdog)"
                                         : "") +
                            ":\n" + tailOfFile(log));
  std::ifstream in(out, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  try {
    return shaderfile::imageFromBytes(bytes.str(), scene.camera.width, scene.camera.height);
  } catch (const std::runtime_error& e) {
    throw ExternalToolError(d.name + ": " + e.what());
  }
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
              (def->vertex_source.empty() ? "" : def->vertex_source.string() + " and ") + def->source.string() +
              " (defined by " + def->file.string() + ") on OpenGL" +
              (edits.empty() ? "" : "; the tool's edits: " + edits);
  r.version_command = {shaderfile::kGlslangTool, "--version"};
  r.version_marker = "Glslang Version";
  r.definition_file = def->file;
  r.missing = [] { return shaderfile::compilersMissing(); };
  r.cannot_express = [def](const Scene& scene) { return shaderfile::shaderCannotExpress(*def, scene); };
  r.render = [def, once](const Scene& scene, const RenderRequest& request, RenderInfo* info) {
    if (const std::string why = shaderfile::shaderCannotExpress(*def, scene); !why.empty()) throw ExportError(why);
    const auto t0 = std::chrono::steady_clock::now();
    const ShaderProgramText& program = compiled(*def, *once);
    std::optional<ScratchFolder> scratch;
    if (request.work_dir.empty()) scratch.emplace("shader-draw");
    const std::filesystem::path dir = scratch ? scratch->dir() : request.work_dir;
    std::filesystem::create_directories(dir);
    Image img = renderInHelper(*def, program, scene, request.timeout_seconds, dir);
    if (info) info->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return img;
  };
  r.prepare_frames = [def, once](const Scene& scene) {
    if (const std::string why = shaderfile::shaderCannotExpress(*def, scene); !why.empty()) throw ExportError(why);
    const ShaderProgramText& program = compiled(*def, *once);
    {  // a frame ends (within the default time-out) before frames are timed in this process
      const ScratchFolder scratch("shader-draw");
      renderInHelper(*def, program, scene, kDefaultToolTimeoutSeconds, scratch.dir());
    }
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
