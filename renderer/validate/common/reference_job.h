// What `xval validate` renders a scene's reference job with, and the size
// of every job's preview: one place for both, read by the validation's
// jobs (validate/validation/run_job.cpp) and by `xval bench`, which times
// such a job with and without the precision probes.
#pragma once

#include "render/renderer.h"
#include "scene/scene.h"

namespace xval {

// The scene's own settings (defaultOptions) on the exact double path, one
// thread: a validate run's parallelism comes from running jobs side by side.
inline RenderOptions referenceJobOptions(const Scene& scene) {
  RenderOptions o = defaultOptions(scene);
  o.precision = Precision::Double;
  o.threads = 1;
  return o;
}

// A job's preview PNG (report images): 8-bit, at most this many pixels a side.
inline constexpr int kPreviewSide = 360;

}  // namespace xval
