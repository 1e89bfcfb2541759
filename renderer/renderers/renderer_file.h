// A renderer defined by a file (format "xval-renderer/1", docs/renderer-file.md):
// someone else's program taking part like a built-in renderer.
//
//   {"format": "xval-renderer/1",
//    "name": "myengine",                      // its id: [a-z0-9-]+, not a registered one
//    "input": "gltf",                         // scene | gltf | pov
//    "command": ["./run_myengine.sh", "{input}", "{output}", "--size", "{width}x{height}"],
//    "version_command": ["./run_myengine.sh", "--version"],
//    "timeout_s": 300}                        // optional; default: the command's --timeout
//
// Placeholders, replaced anywhere inside a word of either command:
// {input} the input (the resolved scene JSON, the glTF file, or the POV-Ray
// export folder), {scene} the resolved scene JSON (texture and model paths
// absolute), {output} the image to write (an EXR or a 16-bit PNG: read by
// its content), {work} a scratch folder, {width} {height} the image size,
// {spp} the scene's samples per pixel. Any other {...} is refused when the
// file is read. A program path with a '/' is relative to the definition
// file's folder; a bare name is looked up on PATH.
//
// The command runs without a shell (process/run_process.h) in the render's
// work folder, with the time-out; a missing program, a non-zero exit, a
// time-out, no image, an image of another size, with fewer than 3 channels
// or with NaN or infinite values is an ExternalToolError quoting the tail of
// the program's output, never an image.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderers/renderer.h"

namespace xval::renderers {

inline constexpr const char* kRendererFileFormat = "xval-renderer/1";
// A definition's optional one-line "description", at most this long.
inline constexpr size_t kMaxRendererDescriptionBytes = 300;

// Reads and checks a definition file. Throws SceneError naming the file,
// the field and the value.
Renderer loadRendererFile(const std::filesystem::path& file);

// A user's shader (format "xval-shader/1", docs/shaders.md,
// renderers/shader.cpp): loadRendererFile hands such a file here after
// checking its name as any renderer file's.
Renderer shaderFileRenderer(const std::filesystem::path& file, const nlohmann::json& doc);

// Adds each file's renderer (and its golden set, golden-<name>) to the
// process's registry, by name (not in the order given: the registry's order
// is that of jobs, pairs and reports, which must not change with the order
// of --renderer-file options). Throws naming the file on any error (a
// malformed file, a name already registered).
void registerRendererFiles(const std::vector<std::string>& files);

// The --renderer-file option's help text.
inline constexpr const char* kRendererFileHelp =
    "A renderer defined by a JSON file, taking part like a built-in one (repeatable): a program (format "
    "xval-renderer/1, docs/renderer-file.md) or a shader of yours, HLSL or GLSL, drawn by xval (format "
    "xval-shader/1, docs/shaders.md; this option is how a shader joins every command, there is no --shader)";

}  // namespace xval::renderers
