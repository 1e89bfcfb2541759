// glTF 2.0 exporter (tinygltf): the scene for Blender's importer.
//
// Written: scene.gltf, scene.bin, and a copy of each material's texture
// (common/export_common.h: texture.png, texture_object<k>.png).
//  - one glTF material per material of the scene (the scene's, each
//    object's own), with its shading constants in the material's extras
//    ({"xval_shading": "<JSON text>"}, shading_constants.h, for that
//    material) and the name of its texture copy ({"xval_texture"});
//  - one mesh per object with the reference renderer's very triangles:
//    POSITION, NORMAL, TEXCOORD_0 (same uv convention as ours: glTF's),
//    indices; for Gouraud shading also `_XVAL_GOURAUD` (float VEC3: the
//    model evaluated per vertex by the reference shader, unsaturated);
//  - the texture as PNG with a sampler matching the filter (NEAREST or
//    LINEAR, REPEAT wrapping);
//  - the camera (yfov, aspectRatio) on a node looking down its -Z, and
//    the resolution to render in the scene's extras, {"xval_render":
//    "{width, height, subpixels_per_side}"}: n W x n H for render.spp =
//    n^2 (common/supersample.h; the harness box-filters n x n blocks);
//  - point, spot and directional lights as KHR_lights_punctual (colour
//    normalised to max 1 with the maximum as intensity; a spot's hard cone
//    as outer = cutoff, inner just below it, as the extension requires
//    inner < outer), attenuation in the light's extras;
//  - the lighting model and every parameter in the SCENE's extras
//    (Blender's importer keeps scene extras as Scene custom properties;
//    root-level extras are dropped): {"xval": "<scene JSON text>"}, the
//    scene-file JSON (scene_writer.h) with its texture path replaced;
//  - the scene material's shading constants in the scene's extras too,
//    {"xval_shading": "<JSON text>"} (shading_constants.h), and for
//    flat shading the per-triangle normals (flat_normals.h) as a float
//    VEC3 accessor named by the primitive's extras ("xval_face_normals").
// Strings from the scene appear only as JSON string values (escaped by
// the JSON writer) and are read back as data, never as code.
#pragma once

#include <filesystem>

#include "scene/scene.h"

namespace xval {

// The glTF file's name inside the export folder.
inline constexpr const char* kGltfFileName = "scene.gltf";

struct GltfExport {
  std::filesystem::path gltf, dir;
};

GltfExport exportGltf(const Scene& scene, const std::filesystem::path& dir);

}  // namespace xval
