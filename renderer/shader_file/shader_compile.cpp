// A user's HLSL effect compiled to GLSL 4.50 (shader_file/shader_compile.h).
#include "shader_file/shader_compile.h"

#include <fstream>
#include <sstream>

#include "common/export_common.h"
#include "files/atomic_write.h"
#include "process/run_process.h"

namespace xval::shaderfile {

namespace fs = std::filesystem;

namespace {

// Runs one tool; throws ExternalToolError unless it exits 0 and writes `output`.
void runTool(const ShaderDefinition& d, const std::vector<std::string>& argv, const fs::path& dir,
             const std::string& log_name, const fs::path& output) {
  const fs::path log = dir / log_name;
  const ProcessResult r = runProcess(argv, dir, log, d.timeout_s);
  std::string command;
  for (const std::string& w : argv) command += (command.empty() ? "" : " ") + w;
  if (!r.ok() || !fs::is_regular_file(output) || fs::file_size(output) == 0) {
    // The messages name the prepared copy: name the user's file (same lines).
    std::string tail = tailOfFile(log);
    const std::string copy = (dir / d.source.filename()).string();
    for (size_t at = tail.find(copy); at != std::string::npos; at = tail.find(copy, at + d.source.string().size()))
      tail.replace(at, copy.size(), d.source.string());
    throw ExternalToolError(d.name + ": `" + command + "` (compiling " + d.source.string() + ") " +
                            (r.ok() ? "wrote no " + output.filename().string() : r.describe()) + ":\n" + tail);
  }
}

std::string readGlsl(const ShaderDefinition& d, const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  if (text.rfind("#version 450", 0) != 0)
    throw ExternalToolError(d.name + ": " + std::string(kSpirvCrossTool) + " wrote " + p.string() +
                            " without a leading \"#version 450\": not the GLSL 4.50 asked for");
  return text;
}

}  // namespace

std::string compilersMissing() {
  for (const char* tool : {kGlslangTool, kSpirvCrossTool})
    if (findOnPath(tool).empty())
      return std::string("'") + tool + "' not found on PATH (scripts/install-deps.sh installs glslang-tools and "
                                       "spirv-cross)";
  return "";
}

ShaderProgramText compileShader(const ShaderDefinition& d, const fs::path& dir) {
  if (const std::string m = compilersMissing(); !m.empty()) throw ExternalToolError(d.name + ": " + m);
  if (d.language == "glsl") {
    // Checked by glslang (messages naming the user's files and lines), then
    // compiled as written by the OpenGL context.
    ShaderProgramText out;
    for (const bool vertex : {true, false}) {
      const fs::path& src = vertex ? d.vertex_source : d.source;
      const std::string stage = vertex ? "vert" : "frag";
      const fs::path log = dir / ("glslang-" + stage + ".log");
      const ProcessResult r = runProcess({kGlslangTool, "-S", stage, src.string()}, dir, log, d.timeout_s);
      if (!r.ok())
        throw ExternalToolError(d.name + ": `" + std::string(kGlslangTool) + " -S " + stage + " " + src.string() +
                                "` " + r.describe() + ":\n" + tailOfFile(log));
      std::ifstream in(src, std::ios::binary);
      std::stringstream ss;
      ss << in.rdbuf();
      (vertex ? out.vertex : out.fragment) = ss.str();
    }
    return out;
  }
  // The prepared text under the user's file name: the messages name it.
  const fs::path source = dir / d.source.filename();
  writeFileAtomically(source, d.effect.text);
  ShaderProgramText out;
  for (const bool vertex : {true, false}) {
    const std::string stage = vertex ? "vert" : "frag";
    const fs::path spv = dir / (stage + ".spv"), glsl = dir / (stage + ".glsl");
    runTool(d,
            {kGlslangTool, "-D", "-V", "--hlsl-dx9-compatible", "-S", stage, "-e",
             vertex ? d.vertex_entry : d.fragment_entry, "-o", spv.string(), source.string()},
            dir, "glslang-" + stage + ".log", spv);
    runTool(d, {kSpirvCrossTool, "--version", "450", "--no-es", spv.string(), "--output", glsl.string()}, dir,
            "spirv-cross-" + stage + ".log", glsl);
    (vertex ? out.vertex : out.fragment) = readGlsl(d, glsl);
  }
  return out;
}

}  // namespace xval::shaderfile
