// A case's geometry checks in `xval validate` (results.json
// cases[].geometry_checks[], docs/results-schema.json, and the report's and
// JUnit's view of them): for each job of a geometry-passes renderer
// (Renderer::geometry_passes: blender-import, Blender importing the user's
// original model files), its passes against the reference renderer's
// passes of our loaded triangles, both written by that one job (plan.h),
// compared by validate/geometry_check.h with its own bounds
// (kGeometryTolerance: the image tolerances do not apply to passes).
// A check is no image pair: it has no heat map, and is not counted in the
// pairs' majority (renderers::attribute).
//
// One record per check:
//   renderer  the renderer whose passes are checked ("blender-import")
//   against   the reference renderer's id
//   verdict   "pass" | "fail": the passes compared, within or outside the
//             bounds; "not_expressible": the renderer declared before
//             rendering that it cannot take the scene (a built-in shape,
//             an OFF file): a verdict, not an error, `reason` says why;
//             "error": no usable passes (the render failed, a job not run,
//             an unreadable EXR): `reason` says why
//   reason    fail: the first bound exceeded; not_expressible, error: why
//   metrics   pass, fail: the counts and maxima (geometry_check.h metricsJson)
//   bounds    pass, fail: the bounds they were held to (boundsJson)
// A case passes only when each of its checks passes or is not expressible
// (and its image pairs pass); an error check makes the run's exit status 2.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "validate/geometry_check.h"

namespace xval::validation {

// The records (see above), pure functions of what they say.
nlohmann::ordered_json geometryCheckCompared(const std::string& renderer, const std::string& against,
                                             const GeometryMetrics& m, const GeometryTolerance& tol);
nlohmann::ordered_json geometryCheckNotExpressible(const std::string& renderer, const std::string& against,
                                                   const std::string& why);
nlohmann::ordered_json geometryCheckError(const std::string& renderer, const std::string& against,
                                          const std::string& why);

// True when every record of `checks` (an array; empty: true) passes or is
// not expressible.
bool geometryChecksPass(const nlohmann::ordered_json& checks);
// How many records of `checks` have this verdict.
int geometryChecksWith(const nlohmann::ordered_json& checks, const std::string& verdict);

// How the report and JUnit name a check: "reference-blender-import (geometry)".
std::string geometryCheckName(const std::string& against, const std::string& renderer);

}  // namespace xval::validation
