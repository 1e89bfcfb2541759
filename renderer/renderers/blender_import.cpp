// blender-import: Blender 3.4 imports the scene's ORIGINAL model files with
// its own importers and Cycles renders what each pixel centre's ray first
// hits: mask, depth, uv, object (blender/model_import.h). Its image is
// those passes (render/geometry_passes.h: rgba = (u, v, depth, hit), raw =
// (object + 1, has_uv, edge)), compared not with the reference's render but
// with the reference's passes of our loaded triangles
// (Renderer::geometry_passes; validate/geometry_check.h), so it checks the
// model loader independently of every exporter.
//
// Only for scenes whose every object is a model file of a format Blender
// imports; anything else is refused with the reason (not expressible: a
// verdict, not an error). every_scene = false, as it renders no image to
// pair with the others; geometry_passes = true, so `xval validate` runs it
// by default as each case's geometry check (validate/validation/
// geometry_checks.h) and `xval crosscheck --renderer blender-import` as one.
//
// Parameters (RenderRequest):
//   work_dir         the job (blender-import-*.json), blender-import.log, the EXR
//   timeout_seconds  default kDefaultToolTimeoutSeconds (600)
// Needs `blender` on PATH and import_model.py beside the Blender harness
// script; version: the "Blender ..." line of `blender --version`.
#include "blender/model_import.h"
#include "renderers/renderer.h"

namespace xval::renderers {

Renderer blenderImportRenderer() {
  Renderer r;
  r.id = "blender-import";
  r.display_name = "Blender import";
  r.summary = "Blender 3.4 imports the original model files itself; hit mask, depth and uv against the reference's";
  r.every_scene = false;
  r.geometry_passes = true;
  r.version_command = {"blender", "--version"};
  r.version_marker = "Blender";
  r.missing = [] {
    const std::filesystem::path script = modelImportScript();
    return std::filesystem::is_regular_file(script)
               ? std::string()
               : "Blender import script " + script.string() + " not found (set XVAL_BLENDER_SCRIPT)";
  };
  r.cannot_express = [](const Scene& scene) -> std::string {
    try {
      checkModelImportScene(scene);
    } catch (const ExportError& e) {
      return e.what();
    }
    return "";
  };
  r.render = [id = r.id](const Scene& scene, const RenderRequest& request, RenderInfo* info) {
    ExternalRenderInfo tool;
    const GeometryPasses passes = renderModelImport(id, scene, request.work_dir, request.timeout_seconds, &tool);
    setInfo(info, tool);
    return toImage(passes);
  };
  return r;
}

}  // namespace xval::renderers
