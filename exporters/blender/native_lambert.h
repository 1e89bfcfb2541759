// The native tier: Blender's own Lambert against the reference Lambert.
//
// The scene must be a white Lambert (c0 = 1, untextured base colour 1) lit
// by exactly one point light of colour (I, I, I) with attenuation
// 1/(c + q d^2), c ~ 0 (the physical inverse square), no ambient. Blender,
// importing its KHR light in 'RAW' mode, makes a point light of power
// P = I watts; Cycles' diffuse-direct pass is then
//   DiffDir = P / (4 pi^2) max(N.L, 0) / d^2
// (docs/blender-export.md, Native tier), so DiffDir * 4 pi^2 is the reference
// Lambert I max(N.L, 0) / (c + q d^2) with q = 1 (the reference saturates
// at 1; so does the scaled pass here). Checks geometry, camera
// and light conversion against Blender's own shading, not our node math.
#pragma once

#include "image/image.h"
#include "scene/scene.h"

namespace xval {

// Throws std::runtime_error when the scene is not such a scene.
void checkNativeLambertScene(const Scene& scene);
// Scales Blender's DiffDir in place to the reference's units.
void scaleNativeLambert(const Scene& scene, Image& blender_diffdir);

}  // namespace xval
