// xval-shader-draw: one frame of a user's shader, in a process of its own.
//
//   xval-shader-draw DEFINITION SCENE VERTEX_GLSL FRAGMENT_GLSL OUT
//
// The shader renderer (renderers/shader.cpp) runs it with the render's
// time-out (process/run_process.h): a draw that does not end is killed with
// its process group, and an OpenGL driver's state is never shared with
// another renderer of the calling process (a context made before a fork
// does not work in the child). It reads the definition (xval-shader/1) and
// the scene (as xval wrote it: paths absolute, its budget already
// checked), draws with the compiled GLSL (shader_file/shader_frame.h) and writes
// OUT: width and height (two native ints), then the RGBA and raw floats.
// Exit 0 when OUT is written; 1 with the reason on stderr otherwise.
#include <fstream>
#include <iostream>
#include <sstream>

#include "shader_file/shader_frame.h"
#include "scene/json_reader.h"
#include "scene_file/scene_budget.h"
#include "scene_file/scene_loader.h"
#include "shader_file/shader_image_bytes.h"

namespace {

std::string readFile(const char* path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(std::string(path) + ": cannot be read");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::cerr << "usage: xval-shader-draw DEFINITION SCENE VERTEX_GLSL FRAGMENT_GLSL OUT\n";
    return 1;
  }
  try {
    using namespace xval;
    const nlohmann::json doc = parseJsonText(readJsonFile(argv[1], "shader file"), argv[1]);
    const shaderfile::ShaderDefinition def = shaderfile::loadShaderDefinition(argv[1], doc);
    const Scene scene = loadScene(argv[2], unlimitedBudget());
    const shaderfile::ShaderProgramText program{readFile(argv[3]), readFile(argv[4])};
    const std::string bytes = shaderfile::imageBytes(gl::renderWithShader(scene, def, program));
    std::ofstream out(argv[5], std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out.flush()) throw std::runtime_error(std::string(argv[5]) + ": cannot be written");
  } catch (const std::exception& e) {
    std::cerr << "xval-shader-draw: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
