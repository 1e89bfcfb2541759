// Cross-renderer tolerances: the default in one file (a tolerances.json,
// the toolkit's own is reference/tolerances.json), each exception declared
// by its scene, next to it, in the scene file's `tolerances` field with a
// written reason (docs/scene-format.md, "tolerances").
//
// Which tolerance file: one rule, the same for validate, crosscheck,
// compare and extremes, that does not depend on the working directory
// (findToleranceFile):
//   1. the file given (--tolerances FILE), if any;
//   2. else the nearest `tolerances.json` in the scene file's folder or one
//      of its ancestors up to the scene's set root and no higher
//      (reference/scenes/x.json -> reference/tolerances.json); with several
//      scenes, they must all find the same file;
//   3. else the toolkit's own, reference/tolerances.json of the source tree
//      the executable was built from (toolkitToleranceFile()).
// Commands without a scene (compare, extremes) skip step 2.
//
// The set root (setRootOf): climbing from the scene file's folder, the
// folder holding the first folder named `scenes` on the way (the set
// layout SET/scenes/..., docs/pack.md: SET/scenes/a/x.json -> SET); when
// no folder on the way is named `scenes`, the scene file's own folder. So
// the climb never leaves the user's set: a tolerances.json planted in a
// shared ancestor (/tmp/, a home folder's parent) is never looked at.
//
// Who may own it: a file found by step 2 decides verdicts, so it is used
// only when it (and, if it is a link, the link) is owned by the user
// running xval, by the owner of the scene file, or by root, is not
// writable by others, and lies in a folder others cannot write to (or one
// with the sticky bit, as /tmp). Otherwise findToleranceFile refuses it,
// naming the file, its owner and mode; the user can pass it with
// --tolerances if it is trusted. The file used is printed on every run.
//
// The pair of two external renderers has no declared tolerance: it is
// derived from theirs against the reference (lookupPair).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/compare.h"
#include "scene/scene.h"

namespace xval {

struct ToleranceTable {
  Tolerance default_tolerance;  // from the file's "default"
  std::filesystem::path source;

  // The tolerance for the scene against `renderer` (compared with the
  // reference renderer): the default, with the fields the scene declares
  // for that renderer replaced (a declared metric criterion replaces the
  // default's on the same metric, the default's others stay); `reason` is the declared reason ("" for the
  // default).
  Tolerance lookup(const Scene& scene, const std::string& renderer,
                   std::string* reason = nullptr) const;

  // The tolerance of the pair (a, b). With the reference renderer in the
  // pair (the registry's, renderers/registry.h): lookup() of the other
  // one. Two external renderers a and b, each within (e1 on f1) and (e2 on
  // f2) of the reference: on the pixels where both are within, |a - b| <= |a - ref| + |ref - b| <= e1 + e2 (triangle
  // inequality), and at most (1 - f1) + (1 - f2) of the pixels are outside
  // either (union bound), so the pair is held to e1 + e2 on
  // max(0, f1 + f2 - 1); back faces are left out if either leaves them out.
  // The caps on unexplained pixels add up the same way (c1 + c2): a pixel's
  // class comes from the reference's diagnostics in all three pairs, so a
  // pixel unexplained between a and b is unexplained against the reference
  // in both.
  // Metric criteria (image/metric_criteria.h) are not derived: a pair of
  // two external renderers is held to none, whatever a and b declare. FLIP,
  // SSIM, CIEDE2000, YIQ and the percentiles obey no triangle inequality
  // (CIEDE2000 and FLIP are not metrics in that sense; a percentile of a sum
  // is not bounded by the sum of percentiles over other pixels), and even
  // max and RMSE are taken over each pair's own covered pixels, which
  // differ between the three pairs; so no bound on a - b follows from bounds
  // on a - ref and ref - b. Each declared criterion still decides its
  // renderer's pair with the reference; `reason` names the criteria left
  // out.
  Tolerance lookupPair(const Scene& scene, const std::string& a, const std::string& b,
                       std::string* reason = nullptr) const;
};

// Throws SceneError (file, field, value) on a malformed file; read as a
// scene file is (scene/json_reader.h: a key given twice refused).
ToleranceTable loadTolerances(const std::filesystem::path& file);

// The toolkit's own tolerance file, absolute (fixed when it was built).
std::filesystem::path toolkitToleranceFile();

// The toolkit's own reference scene set, reference/scenes beside that file
// (absolute, fixed when it was built): what validate and golden take when
// given no scenes, whatever the working directory.
std::filesystem::path toolkitSceneSet();
// The default above, for the scenes argument's --help.
std::string defaultScenesHelp();

// The rule above, for --help.
inline constexpr const char* kToleranceFileHelp =
    "Tolerance file. Default: the nearest tolerances.json in the scene file's folder or one of its "
    "ancestors up to the set's root, the folder holding `scenes` (reference/scenes/x.json -> "
    "reference/tolerances.json; all scenes must find the same one; one owned by another user or "
    "writable by others is refused), else the toolkit's own reference/tolerances.json; never the "
    "working directory. The file used is printed and recorded (docs/scene-format.md, \"Which "
    "tolerance file\")";

// A tolerance file found by the rule above.
struct ToleranceFile {
  std::filesystem::path path;  // absolute, lexically normal
  std::string found_by;        // "given", "nearest to the scene" or "the toolkit's own"
  // The path relative to the working directory when it lies below it,
  // else absolute (for messages and provenance only).
  std::string shown() const;
  std::string describe() const { return shown() + " (" + found_by + ")"; }
};

// The set root of a scene file (the rule above), absolute and lexically
// normal.
std::filesystem::path setRootOf(const std::filesystem::path& scene_file);

// The rule above. `given` empty: not given (a file given is not opened
// here: loadTolerances says what is wrong with it). Throws
// std::runtime_error when the scenes find different files (naming two of
// them and what each found), or when the file found is not trusted
// (owner, mode: naming the file, its owner and what is allowed).
ToleranceFile findToleranceFile(const std::filesystem::path& given,
                                const std::vector<std::filesystem::path>& scene_files);

}  // namespace xval
