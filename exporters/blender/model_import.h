// The Blender-import check: Blender 3.4 imports each scene object's
// ORIGINAL model file with its own importer (not our loader's triangles),
// and Cycles renders its geometry passes (render/geometry_passes.h) at the
// pixel centres:
//   blender -b --factory-startup -P exporters/blender/import_model.py -- --job JOB.json
// The job is a JSON file (paths, matrices, camera as data: nothing is
// formatted into Python).
//
// Frames. Our loader keeps the file's coordinates (docs/model-files.md), so
// a file point q lands in the scene at T q (T: the object's transform);
// the glTF export's convention puts scene point p in Blender at C p,
// C (x, y, z) = (x, -z, y) (docs/blender-export.md). Each importer maps
// q to I q: I = identity for OBJ (forward_axis Y, up_axis Z), PLY and STL
// (axis_forward Y, axis_up Z), I = C for glTF / GLB (the importer's y-up
// conversion, after the file's node transforms). Every object the importer
// adds without a parent is then placed by C T I^-1, so it lands at C T q
// exactly when both readers agree. The camera: CameraRays' (camera/
// camera.h) right, up and -forward as the columns of its rotation, taken
// by C; vertical field of view fov_y (sensor fit VERTICAL).
//
// Blender's passes: hit = Combined alpha (1 sample, transparent film),
// depth = the Depth pass (Cycles: the distance along the view axis, as
// the reference's t (d . forward)), uv = the UV pass with v turned down
// (1 - v: Blender's v runs up, the scene's down), object = IndexOB - 1
// (pass_index k + 1 for scene object k).
#pragma once

#include <filesystem>

#include "common/export_common.h"
#include "render/geometry_passes.h"
#include "scene/scene.h"

namespace xval {

// The script: import_model.py beside the Blender harness script
// (blenderScript(): $XVAL_BLENDER_SCRIPT or the source tree's).
std::filesystem::path modelImportScript();

// Throws ExportError, naming the object and why, unless every object is a
// model file of a format Blender 3.4 imports (OBJ, PLY, STL, glTF, GLB;
// not OFF: Blender has no OFF importer) at a path Blender reads as it is,
// naming no file the loader's rule refuses (geometry/model_references.h:
// an absolute path, a ".." out of the model's folder, a URL, a FIFO, in
// any field Blender's importer reads), so Blender never opens one.
void checkModelImportScene(const Scene& scene);

// Blender's passes of the scene (see above), at the camera's resolution.
// `renderer`: the id of the registry entry rendering it
// (renderers/blender_import.cpp), which labels the errors and names the
// files: the job, the log (<renderer>.log) and the EXR go in work_dir. Throws
// ExportError (checkModelImportScene) or ExternalToolError (Blender
// missing, failing, timing out after timeout_seconds, or writing an
// unusable image).
GeometryPasses renderModelImport(const std::string& renderer, const Scene& scene, const std::filesystem::path& work_dir, double timeout_seconds,
                                 ExternalRenderInfo* info = nullptr);

}  // namespace xval
