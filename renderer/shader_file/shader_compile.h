// A user's HLSL effect compiled to GLSL 4.50 by outside tools, each run
// as a process with the definition's time-out (process/run_process.h):
//
//   glslangValidator -D -V --hlsl-dx9-compatible -S vert -e VERTEX_ENTRY -o vert.spv SOURCE
//   glslangValidator -D -V --hlsl-dx9-compatible -S frag -e FRAGMENT_ENTRY -o frag.spv SOURCE
//   spirv-cross --version 450 --no-es vert.spv --output vert.glsl   (and frag)
//
// A GLSL definition: each stage checked by `glslangValidator -S vert|frag
// FILE` (its messages name the user's file and line), then compiled as
// written by the OpenGL context.
//
// SOURCE is the prepared effect (shader_file/effect_source.h: the user's
// file with the tool's edits, same lines) written under the user's file
// name, so the compiler's messages name the user's file and line. A tool
// that is missing, fails, times out or writes no GLSL 4.50 is an
// ExternalToolError naming the tool, what happened and the tail of its
// output; never a program.
#pragma once

#include <filesystem>
#include <string>

#include "shader_file/shader_definition.h"

namespace xval::shaderfile {

inline constexpr const char* kGlslangTool = "glslangValidator";
inline constexpr const char* kSpirvCrossTool = "spirv-cross";

struct ShaderProgramText {
  std::string vertex, fragment;  // GLSL 4.50
};

// Compiles in `dir` (an existing folder the caller owns).
ShaderProgramText compileShader(const ShaderDefinition& d, const std::filesystem::path& dir);

// Why the compilers cannot run here ("" when they can): a tool not on PATH.
std::string compilersMissing();

}  // namespace xval::shaderfile
