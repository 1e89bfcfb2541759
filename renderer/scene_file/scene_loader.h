// Scene files: JSON -> validated Scene (docs/scene-format.md).
#pragma once

#include "files/output_folder.h"
#include "scene/json_reader.h"
#include "scene/scene.h"
#include "scene_file/scene_budget.h"
#include "scene/scene_limits.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace xval {

// Reads and validates a scene file. Throws SceneError naming the file, the
// field path and the bad value. Relative texture paths resolve against the
// scene file's folder; the texture file must exist and be readable.
// The scene must also fit `budget` at its own render.spp
// (scene_file/scene_budget.h); a command that renders it otherwise checks again.
Scene loadScene(const std::filesystem::path& file, const Budget& budget = Budget{});

// The text of a JSON file xval reads (scene, spec, tolerance file, validate's
// plan and job records): refused, as a SceneError naming the file, unless it
// is a regular file (not a FIFO or a folder) of at most kMaxSceneFileBytes.
// `what` names it in messages ("scene file").
std::string readJsonFile(const std::filesystem::path& file, const std::string& what);

// Why a JSON file found in a scene folder is not a scene, or "" when it is
// one (or cannot be told: then loading it reports the problem). Not a scene:
// a file whose top-level "format" names another xval format
// ("xval-generate/1", "xval-renderer/1", ...), and a tolerance file (named
// tolerances.json, see validate/tolerances.h). Unreadable or malformed files
// count as scenes, so their errors are not lost.
std::string nonSceneReason(const std::filesystem::path& file);

// The renderers a scene's `tolerances` may name: the renderer registry
// (renderers/registry.h) installs its ids here (every renderer compared
// against the reference). In a program without the registry a scene
// declaring any tolerance is refused, saying so.
void setToleranceRenderers(std::function<std::vector<std::string>()> ids);
// The renderers a scene's `renderers` may name: every id of the registry,
// installed the same way. Without it a scene naming renderers is refused.
void setSceneRenderers(std::function<std::vector<std::string>()> ids);

// Same, from text already in memory; `file` is used in messages and to
// resolve relative paths.
Scene parseScene(const std::string& text, const std::filesystem::path& file,
                 const Budget& budget = Budget{});

// What xval validate writes or reads at the top of its output folder,
// beside the scenes' case folders: no scene may be named like one of them
// (nor like their temporary "<name>.partial-..." folders).
inline constexpr const char* kReservedSceneNames[] = {
    "jobs.json",  "results.json", "report.html", "p999.dat",  "p999.gp", "p999.png",
    "p999.log",   "heat_scale.png", "version.log", kLockFileName, "extremes", "tradeoff"};

// The one rule for a scene name, wherever it comes from (a scene file, a
// generated scene, validate's plan): what is wrong with it ("expected
// ..."), empty when it is usable.
//   Loaded: one path component (not empty, ".", ".."; no '/', NUL), UTF-8,
//     at most kMaxSceneNameBytes, and no character a tool misreads in a
//     path ('\\', '?'). The loader (and so the generator) refuses others.
//   CaseFolder: also no control characters (the name is in every progress
//     line) and none of kReservedSceneNames: what `xval validate` checks
//     before the name names a case folder in its output folder.
enum class SceneNameUse { Loaded, CaseFolder };
std::string sceneNameProblem(const std::string& name, SceneNameUse use = SceneNameUse::Loaded);

}  // namespace xval
