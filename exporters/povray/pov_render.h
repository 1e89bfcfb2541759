// Rendering a scene with POV-Ray: export, run `povray scene.ini` with a
// time-out, read the 16-bit PNG back as an Image (linear values, alpha =
// hit mask), so the comparison never cares which renderer made an image.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "image/image.h"
#include "scene/scene.h"

namespace xval {

// An external renderer is missing, failed, timed out or wrote no image.
class ExternalToolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ExternalRenderInfo {
  double seconds = 0.0;         // the tool's whole process, wall time
  std::filesystem::path log;
  double render_seconds = -1.0;  // the render alone, as the tool reports it (-1: not reported)
};

inline constexpr double kDefaultToolTimeoutSeconds = 600.0;

// work_dir receives the export, the tool's log and its raw output.
Image renderWithPovray(const Scene& scene, const std::filesystem::path& work_dir,
                       double timeout_seconds, ExternalRenderInfo* info = nullptr);

}  // namespace xval
