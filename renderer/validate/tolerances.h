// Declared tolerances for cross-renderer comparisons: one file
// (reference/tolerances.json) with the default and the per-case
// exceptions; every exception that loosens the default must carry a
// written reason, or the file is rejected.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/compare.h"

namespace xval {

struct ToleranceCase {
  std::vector<std::string> scenes;
  std::string renderer;  // "povray", "blender"
  Tolerance tolerance;
  std::string reason;
};

struct ToleranceTable {
  Tolerance default_tolerance;
  std::vector<ToleranceCase> cases;
  std::filesystem::path source;

  // The tolerance for (scene, renderer) and, when it is an exception, why.
  Tolerance lookup(const std::string& scene, const std::string& renderer,
                   std::string* reason = nullptr) const;
};

// Throws SceneError (file, field, value) on a malformed file.
ToleranceTable loadTolerances(const std::filesystem::path& file);

}  // namespace xval
