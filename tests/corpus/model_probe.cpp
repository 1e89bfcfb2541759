// xval_model_probe [--render] [--keep-scene SCENE] FILE...: loads each model file with
// loadModelFile and prints one line per file:
//   loaded <file>: <P> primitives, <T> triangles, <V> vertices
//   refused <message>            (a ModelFileError: names the file and why)
// With --render, a loaded file is then rendered as `xval render` would
// render a scene of it: a scene file written to a temporary folder names
// it as its one mesh object (untextured classic Phong, one point light,
// 32 x 32 pixels, the camera on the diagonal of the model's bounding box,
// looking at its centre from 1.2 bounding radii / sin(fov/2) away), read by
// loadScene and rendered by both paths (float and double). The line then
// ends in "; rendered: <C> of 1024 pixels covered (float), <D> (double)".
// With --keep-scene, the scene of the (one) file is written to SCENE, its
// "name" SCENE's stem, and kept when the file loaded and rendered (the
// corpus's Blender sweep validates it: model_corpus.cpp, --blender).
// A SceneError (the scene loader's error, naming the model file) is
// printed as "refused"; a rendered pixel that is not finite is a failure.
// Exit status 0 when every file was loaded (and rendered) or refused; 2
// when anything else escaped the loader or the renderer (an exception of
// another type, a non-finite pixel: a bug). A crash or a hang is seen by
// the caller (tests/corpus/model_corpus.cpp runs one probe per file, with
// a time-out).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "geometry/model_file.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"

namespace fs = std::filesystem;

namespace {

// The scene of a loaded model (see the top of the file); returns its path.
fs::path writeProbeScene(const xval::Model& m, const fs::path& model, const fs::path& file) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const auto& p : m.primitives)
    for (const auto& v : p.mesh.positions) lo = glm::min(lo, v), hi = glm::max(hi, v);
  const glm::dvec3 c = 0.5 * (lo + hi);
  const double r = std::max(0.5 * glm::length(hi - lo), 1e-6 * std::max(1.0, glm::length(c)));
  const double fov_deg = 45.0, dist = 1.2 * r / std::sin(0.5 * fov_deg * M_PI / 180.0);
  const glm::dvec3 eye = c + dist * glm::normalize(glm::dvec3(0.3, 0.4, 1.0));
  const nlohmann::json scene = {
      {"format", "xval-scene/1"},
      {"name", file.stem().string()},
      {"camera",
       {{"position", {eye.x, eye.y, eye.z}}, {"target", {c.x, c.y, c.z}}, {"fov_y_deg", fov_deg}, {"width", 32},
        {"height", 32}}},
      {"objects", {{{"shape", "mesh"}, {"path", fs::absolute(model).string()}}}},
      {"material", {{"model", {{"type", "classic_phong"}, {"variant", "paper"}, {"shininess", 20}}}}},
      {"lights", {{{"type", "point"}, {"position", {eye.x + r, eye.y + 2 * r, eye.z}}}}},
      {"shading", "phong"}};
  std::ofstream(file) << scene.dump(2);
  return file;
}

// Covered pixels of a frame; throws when a pixel is not finite.
int coveredPixels(const xval::Image& img, const char* path) {
  int covered = 0;
  for (size_t i = 0; i < img.rgba.size(); ++i)
    if (!std::isfinite(img.rgba[i])) throw std::runtime_error(std::string(path) + " path: a pixel is not finite");
  for (size_t i = 3; i < img.rgba.size(); i += 4) covered += img.rgba[i] > 0.0f;
  return covered;
}

}  // namespace

int main(int argc, char** argv) {
  int status = 0;
  bool render = false;
  fs::path keep;
  const fs::path dir = fs::temp_directory_path() / ("xval_model_probe_" + std::to_string(getpid()));
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--render") == 0) {
      render = true;
      continue;
    }
    if (std::strcmp(argv[i], "--keep-scene") == 0 && i + 1 < argc) {
      keep = fs::absolute(argv[++i]);
      continue;
    }
    bool kept = false;
    try {
      xval::ModelLoadOptions o;
      o.uvs = xval::UvRequirement::ModelTextures;
      const xval::Model m = xval::loadModelFile(argv[i], o);
      std::ostringstream line;
      line << "loaded " << argv[i] << ": " << m.primitives.size() << " primitives, " << m.triangleCount()
           << " triangles, " << m.vertexCount() << " vertices";
      if (render) {
        fs::create_directories(dir);
        const xval::Scene scene = xval::loadScene(writeProbeScene(m, argv[i], keep.empty() ? dir / "scene.json" : keep));
        int covered[2];
        for (const xval::Precision p : {xval::Precision::Float, xval::Precision::Double}) {
          xval::RenderOptions opt = xval::defaultOptions(scene);
          opt.precision = p, opt.threads = 1;
          covered[p == xval::Precision::Double] =
              coveredPixels(xval::renderScene(scene, opt), p == xval::Precision::Float ? "float" : "double");
        }
        line << "; rendered: " << covered[0] << " of 1024 pixels covered (float), " << covered[1] << " (double)";
        kept = !keep.empty();
      }
      for (const std::string& n : m.notes) line << "; note: " << n;
      std::cout << line.str() << "\n";
    } catch (const xval::ModelFileError& e) {
      std::cout << "refused " << e.what() << "\n";
    } catch (const xval::SceneError& e) {
      std::cout << "refused " << e.what() << "\n";
    } catch (const std::exception& e) {
      std::cout << "escaped " << argv[i] << ": " << e.what() << "\n";
      status = 2;
    }
    std::error_code ec;
    if (!kept && !keep.empty()) fs::remove(keep, ec);
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  return status;
}
