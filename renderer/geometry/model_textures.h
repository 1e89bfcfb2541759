// Texture source "model" resolved: the form every renderer and exporter
// shades, so that none of them needs to know the source.
//
// An object whose material (its own or the scene's) has texture source
// "model" becomes one object per primitive of its model file, in the
// file's order, each with
//   shape:     the same model file, holding that one primitive;
//   transform: the object's;
//   material:  the object's, with texture = the primitive's base-colour
//              texture as source "image" (an external file, or the bytes
//              of an image embedded in the model file) and the material's
//              filter; a primitive whose material assigns no texture has
//              no texture, so it is shaded with the material's base_color.
// Every other object is kept as it is. The meshes are the same, in the
// same order, as those of the scene before (geometry/scene_meshes.h):
// only the material each is shaded with changes.
#pragma once

#include "scene/scene.h"

namespace xval {

// True when some object's material has texture source "model".
bool usesModelTextures(const Scene& scene);

// The scene with every texture source "model" resolved (see above); the
// scene itself when none is used.
Scene resolveModelTextures(const Scene& scene);

}  // namespace xval
