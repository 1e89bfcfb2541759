// The total budget of one render: triangles over all objects, samples
// (width x height x spp) and an estimate of the memory, checked when a scene
// is loaded and again when a command overrides its settings, before
// anything is tessellated or allocated. Each limit alone (per mesh, per
// side, spp) is checked by the loader; this bounds their product.
//
// Defaults (a render that fits a few GiB and a few minutes on a small
// machine); a command's --max-triangles, --max-samples, --max-memory-mb or
// --allow-large raises them (docs/robustness.md):
//   triangles  16,777,216  (a 4096 x 2048 sphere)
//   samples    268,435,456 (4096 x 4096 at 16 spp)
//   memory     4096 MiB, estimated as
//              kBytesPerTriangle x triangles + kBytesPerPixel x pixels
//              (measured: 217 bytes per triangle in double, 190 in float;
//              104 bytes per pixel with diagnostics; both rounded up).
#pragma once

#include <string>

#include "scene/scene.h"

namespace xval {

struct Budget {
  long long max_triangles = 16ll << 20;
  long long max_samples = 256ll << 20;
  long long max_memory_mb = 4096;
};

// What --allow-large sets: only the loader's own limits remain.
Budget unlimitedBudget();

inline constexpr long long kBytesPerTriangle = 256;
inline constexpr long long kBytesPerPixel = 128;

// Triangles the scene's objects tessellate to (as tessellate() makes them).
long long triangleCount(const Shape& s);

// Throws SceneError naming the scene file, the field, the value and the
// limit (and the option that raises it) when the scene, rendered at `spp`
// with its objects' segment counts multiplied by tessellation_factor in
// each direction, exceeds the budget.
void checkBudget(const Scene& scene, int spp, const Budget& budget, double tessellation_factor = 1.0);

}  // namespace xval
