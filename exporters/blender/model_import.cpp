#include "blender/model_import.h"


#include <cmath>

#include <nlohmann/json.hpp>

#include "blender/blender_render.h"
#include "blender/multilayer_exr.h"
#include "camera/camera.h"
#include "files/atomic_write.h"
#include "geometry/model_file.h"
#include "geometry/model_references.h"
#include "geometry/transform.h"
#include "image/image.h"
#include "process/run_process.h"

namespace xval {

std::filesystem::path modelImportScript() { return blenderScript().parent_path() / "import_model.py"; }

namespace {

// The Blender importer of a loaded model's format ("" for none).
std::string importerFormat(const std::string& format) {
  if (format == "obj" || format == "ply" || format == "stl") return format;
  if (format == "gltf" || format == "glb") return "gltf";
  return "";
}

// Blender reads '\\' in a path as a folder separator.
void requireNoBackslash(const std::filesystem::path& p, const std::string& what) {
  if (p.string().find('\\') != std::string::npos)
    throw ExportError(what + ": " + p.string() + " contains '\\', which Blender reads as a folder separator");
}

// C: the scene's frame to Blender's, (x, y, z) -> (x, -z, y).
glm::dvec3 toBlender(glm::dvec3 p) { return {p.x, -p.z, p.y}; }

// A 4 x 4 matrix as rows, from the images of the axes and the origin.
nlohmann::json rows(glm::dvec3 c0, glm::dvec3 c1, glm::dvec3 c2, glm::dvec3 o) {
  nlohmann::json m = nlohmann::json::array();
  for (int r = 0; r < 3; ++r) m.push_back({c0[r], c1[r], c2[r], o[r]});
  m.push_back({0.0, 0.0, 0.0, 1.0});
  return m;
}

// C T I^-1 for an importer that maps q to I q (I = C for glTF, else the
// identity): the matrix Blender places the imported objects by.
nlohmann::json placement(const ObjectTransform& t, bool importer_converts_y_up) {
  const Affine a = toAffine(t);
  // Column k of C T I^-1 is C T (I^-1 e_k); I^-1 = C^-1: (x, y, z) -> (x, z, -y).
  auto inverseI = [&](glm::dvec3 e) { return importer_converts_y_up ? glm::dvec3(e.x, e.z, -e.y) : e; };
  auto column = [&](glm::dvec3 e) { return toBlender(a.linear * inverseI(e)); };
  return rows(column({1, 0, 0}), column({0, 1, 0}), column({0, 0, 1}), toBlender(a.offset));
}

nlohmann::json jobOf(const Scene& scene, const std::filesystem::path& out) {
  const CameraRays cam(scene.camera);
  // The clip range of the glTF export (gltf/gltf_exporter.cpp): wide enough
  // for any scene within the precision limits.
  const double scale = std::max(1.0, glm::length(scene.camera.position));
  nlohmann::json j = {
      {"out", out.string()},
      {"width", scene.camera.width},
      {"height", scene.camera.height},
      {"camera",
       {{"matrix_world", rows(toBlender(cam.right), toBlender(cam.up), -toBlender(cam.forward), toBlender(cam.origin))},
        {"fov_y_deg", scene.camera.fov_y_deg},
        {"clip_start", 1e-6 * scale},
        {"clip_end", 1e9 * scale}}},
      {"objects", nlohmann::json::array()}};
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const auto& mf = std::get<MeshFile>(scene.objects[k].shape);
    const std::string fmt = importerFormat(mf.model->format);
    // The file the loader read (canonical): Blender resolves the names in
    // it against this file's folder, as the loader and the check of
    // checkModelImportScene do, not against a symlink's.
    j["objects"].push_back({{"path", mf.model->file.string()},
                            {"format", fmt},
                            {"matrix", placement(scene.objects[k].transform, fmt == "gltf")},
                            {"pass_index", k + 1}});
  }
  return j;
}

// Blender's multilayer EXR as passes. Throws ExternalToolError for an image
// of another size, without a pass, or with values no render gives.
GeometryPasses readPasses(const std::filesystem::path& file, const Scene& scene) {
  const int width = scene.camera.width, height = scene.camera.height;
  const MultilayerChannels in =
      readMultilayerChannels(file, width, height, {"Combined.A", "Depth.Z", "UV.U", "UV.V", "IndexOB.X"});
  const int nc = in.nchannels;
  const std::vector<float>& buf = in.pixels;
  const int a = in.index[0], z = in.index[1], u = in.index[2], v = in.index[3], ob = in.index[4];
  GeometryPasses g(width, height);
  for (size_t p = 0; p < g.size(); ++p) {
    const float* px = &buf[p * nc];
    const float alpha = px[a];
    auto bad = [&](const std::string& what) {
      return ExternalToolError(file.string() + ": pixel x=" + std::to_string(p % width) + ", y=" +
                               std::to_string(p / width) + ": " + what);
    };
    if (alpha != 0.0f && alpha != 1.0f)
      throw bad("alpha " + std::to_string(alpha) + " (one sample per pixel gives 0 or 1)");
    if (alpha == 0.0f) continue;
    if (!std::isfinite(px[z]) || !(px[z] > 0.0f) || !std::isfinite(px[u]) || !std::isfinite(px[v]))
      throw bad("depth " + std::to_string(px[z]) + ", uv (" + std::to_string(px[u]) + ", " + std::to_string(px[v]) +
                "): not a finite hit");
    const float index = px[ob];
    if (!(index >= 1.0f && index <= float(scene.objects.size())) || index != std::floor(index))
      throw bad("object index " + std::to_string(index) + " (expected 1 to " + std::to_string(scene.objects.size()) +
                ")");
    g.hit[p] = 1.0f;
    g.depth[p] = px[z];
    g.u[p] = px[u];
    g.v[p] = 1.0f - px[v];
    g.has_uv[p] = 1.0f;
    g.object[p] = int32_t(index) - 1;
  }
  return g;
}

}  // namespace

void checkModelImportScene(const Scene& scene) {
  if (scene.objects.empty()) throw ExportError(scene.name + ": the Blender-import check needs model-file objects");
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const std::string what = scene.name + ": objects[" + std::to_string(k) + "]";
    const auto* mf = std::get_if<MeshFile>(&scene.objects[k].shape);
    if (!mf)
      throw ExportError(what + ": a built-in shape, not a model file: the Blender-import check compares "
                        "Blender's import of the scene's model files with our loader's, so every object must be one");
    if (importerFormat(mf->model->format).empty())
      throw ExportError(what + ": " + mf->path.string() + ": format '" + mf->model->format +
                        "': Blender 3.4 has no importer for it (it imports OBJ, PLY, STL, glTF and GLB)");
    requireNoBackslash(mf->model->file, what + ".path");
    // Blender's importers open every file the model names, not only those
    // our loader opens (a glTF's normal map, an OBJ material's bump map):
    // each must pass the loader's rule for files inside the model's folder
    // (geometry/model_references.h) before Blender is started on it.
    if (const std::string refused = refusedModelReference(mf->model->file); !refused.empty())
      throw ExportError(what + ": " + refused + " (Blender's importer would open it; the check reads only files "
                        "inside the model's folder)");
  }
}

GeometryPasses renderModelImport(const std::string& renderer, const Scene& scene, const std::filesystem::path& work_dir, double timeout_seconds,
                                 ExternalRenderInfo* info) {
  checkModelImportScene(scene);
  const std::filesystem::path script = modelImportScript();
  if (!std::filesystem::is_regular_file(script))
    throw ExternalToolError("Blender import script " + script.string() + " not found (set XVAL_BLENDER_SCRIPT)");
  const std::filesystem::path abs_work = std::filesystem::absolute(work_dir);
  requireNoBackslash(abs_work, "the work folder");
  requireNoBackslash(std::filesystem::absolute(script), "the script");
  // This attempt's own names: nothing an earlier Blender left is read.
  const std::string token = attemptToken();
  const std::filesystem::path out = abs_work / (renderer + "-" + token + ".exr");
  const std::filesystem::path job = abs_work / (renderer + "-" + token + ".json");
  const std::filesystem::path log = abs_work / (renderer + ".log");
  writeFileAtomically(job, jobOf(scene, out).dump(1) + "\n");
  const std::vector<std::string> argv = {"blender", "-b", "--factory-startup", "-noaudio", "-P",
                                         std::filesystem::absolute(script).string(), "--", "--job", job.string()};
  const ProcessResult r = runProcess(argv, work_dir, log, timeout_seconds);
  if (info) *info = {r.seconds, log, -1.0};
  requireToolOutput(renderer, job, r, out);
  try {
    return readPasses(out, scene);
  } catch (const std::exception& e) {
    throw ExternalToolError(std::string("blender-import wrote an unusable image: ") + e.what());
  }
}

}  // namespace xval
