// Rendering a scene with POV-Ray: export, run `povray scene.ini` with a
// time-out, read the 16-bit PNG back as an Image (linear values, alpha =
// hit mask), so the comparison never cares which renderer made an image.
// At render.spp = n^2 POV-Ray renders n W x n H pixels, which are box-
// filtered to W x H (common/supersample.h).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "common/export_common.h"
#include "image/image.h"
#include "povray/pov_exporter.h"
#include "scene/scene.h"

namespace xval {

// `renderer`: the id of the registry entry rendering it (renderers/povray.cpp),
// which labels the errors. work_dir receives the export (through `through`: the export's scene.ini
// names scene.png; this attempt's own output name is given to povray on its
// command line, after the ini), the tool's log and its raw output.
Image renderWithPovray(const std::string& renderer, const Scene& scene, const std::filesystem::path& work_dir,
                       double timeout_seconds, ExternalRenderInfo* info = nullptr,
                       const ExportThrough& through = {}, PovTier tier = PovTier::Emission);

}  // namespace xval
