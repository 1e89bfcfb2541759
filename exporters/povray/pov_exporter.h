// POV-Ray 3.7 exporter: the scene as a self-contained folder that POV-Ray
// renders, in ONE render, into the image the reference renderer makes.
//
// Written: scene.pov, scene.ini (every option that matters; render with
// `povray scene.ini` from the folder), a copy of each material's texture,
// README.txt. No user string reaches the SDL except, made safe, in a
// comment: the textures are always copied to "texture.png" (the scene's
// material) and "texture_object<k>.png" (object k's own).
// Objects with materials of their own: each material has its own texture
// function, pigment tree and finish (declared names suffixed _object<k>),
// and each object is a light_group of its material's light sources with
// global_lights off (their colours depend on the material).
//
// How each part of a model is computed (docs/povray-export.md):
//  - geometry: mesh2 with the same positions, normals (Phong shading; none
//    for flat shading, so POV-Ray uses the face normal) and uv_vectors
//    (u, 1 - v: POV-Ray's image_map runs v bottom-up).
//  - camera: location, direction, right and up set explicitly so that the
//    primary ray of pixel (i, j) is the reference renderer's.
//  - render.spp = n^2: scene.ini asks for n W x n H pixels, one sample
//    through each centre, which are the reference renderer's n x n
//    sub-pixel samples (common/supersample.h); the harness box-filters
//    them. POV-Ray's antialiasing stays off (it averages unclipped samples).
//  - everything but the specular term is an emission pigment built from
//    blend maps (pigment_tree.h) over
//      * slope { point_at P } / slope { -dir } with `sine_wave frequency
//        -0.5 phase 0.75`, which is exactly (1 + N.L) / 2, so any piecewise
//        linear function of N.L is a pigment_map;
//      * position functions for attenuation 1/(c + l d + q d^2) and for the
//        spot cone;
//      * the texture colour through function { pigment { image_map } }.
//  - the specular term is POV-Ray's own `phong` (exactly
//    ks max(R.V,0)^n Lc att, white), with `double_illuminate` to remove its
//    N.L > 0 gate (the paper does not gate), `fade_distance`/`fade_power`
//    or a texture_map over the attenuation function for attenuation, and a
//    hard-edged spotlight for the cone.
//  - Gouraud: per-vertex colours (the model evaluated at the vertices by
//    the reference shader) in a per-triangle image that POV-Ray's bilinear
//    lookup interpolates exactly (gouraud_image.h).
// The shading is first built as values (pov_shading.h: the emission tree,
// the light sources, the finish), which this writes as SDL.
// What cannot be exact in one render is refused with an ExportError that
// says why (never an approximation in silence).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "common/export_common.h"
#include "common/supersample.h"
#include "scene/scene.h"

namespace xval {

struct PovExport {
  std::filesystem::path pov, ini, dir;
  std::string output_name = "scene.png";  // written by POV-Ray into dir
  SubpixelGrid grid;                       // the size POV-Ray renders (n W x n H)
};

// What the materials are written as: xval's model computed in emission
// pigments (above; renderer povray), or POV-Ray's own finish (the native
// tier, povray/pov_native.h; renderer povray-native): there the camera,
// geometry, textures (a uv_mapping image_map pigment) and .ini are the
// same, each material is `texture { pigment { C } nativeFinish }` and the
// lights are light sources with ambient_light; no double_illuminate.
enum class PovTier { Emission, Native };

// `output_name`: the image POV-Ray is told to write (the render harness
// names it per attempt, povray/pov_render.h).
PovExport exportPov(const Scene& scene, const std::filesystem::path& dir,
                    const std::string& output_name = "scene.png", PovTier tier = PovTier::Emission);

}  // namespace xval
