// Cross-renderer tolerances: the default in one file
// (reference/tolerances.json), each exception declared by its scene, next to
// it, in the scene file's `tolerances` field with a written reason
// (docs/scene-format.md).
#pragma once

#include <filesystem>
#include <string>

#include "image/compare.h"
#include "scene/scene.h"

namespace xval {

struct ToleranceTable {
  Tolerance default_tolerance;
  std::filesystem::path source;

  // The tolerance for the scene against `renderer` and, when the scene
  // declares its own, why.
  Tolerance lookup(const Scene& scene, const std::string& renderer,
                   std::string* reason = nullptr) const;
};

// Throws SceneError (file, field, value) on a malformed file.
ToleranceTable loadTolerances(const std::filesystem::path& file);

}  // namespace xval
