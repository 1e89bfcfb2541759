// The paper's Figure 1 claims (Kotsarenko & Ramos 2012, section 4), judged
// on the colour statistics of the reference renders of the six Figure 1
// scenes (validate/colour_stats.h; conditions fixed in docs/paper-claims.md):
//
//   specular only, classic Phong is grey whatever the texture:
//       grey(phong_specular) >= 95%
//   specular only, the YIQ model follows the texture:
//       grey(yiq_specular) <= 20% and hue_error(yiq_specular) <= 15 deg
//   light behind, classic Phong greys out and YIQ does not:
//       grey(phong_behind) >= 2 grey(yiq_behind) and C*(yiq_behind) > C*(phong_behind)
//   light in front, YIQ is no worse than classic Phong:
//       hue_error(yiq_front) <= hue_error(phong_front) + 2 deg
//
// The compare step of `xval validate` stores the verdicts in results.json
// (`paper_claims`); the report only shows them.
#pragma once

#include <nlohmann/json.hpp>

namespace xval {

// The scenes the claims are judged on, in the order the report shows them.
inline constexpr const char* kFigure1Scenes[6] = {"fig1_phong_front", "fig1_phong_behind", "fig1_phong_specular",
                                                 "fig1_yiq_front",   "fig1_yiq_behind",   "fig1_yiq_specular"};

// From results.json's `cases` (each with `scene` and, for a successful
// reference render, `colour_stats`): {"scenes": [the six names],
// "claims": [{"claim", "condition", "measured", "holds"}, ...]}, or null
// when one of the six scenes is not in the run or has no colour_stats.
nlohmann::ordered_json paperClaims(const nlohmann::ordered_json& cases);

}  // namespace xval
