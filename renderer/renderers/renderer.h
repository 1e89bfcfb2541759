// A renderer, as every command sees it: something that turns a Scene into
// an Image (linear colour, alpha = hit mask), with an id, a name, a version,
// and a way to say, before rendering, whether it can express a scene.
//
// The renderers are listed in one place, the registry (renderers/registry.h);
// each built-in renderer is one file beside it (reference.cpp, povray.cpp,
// povray_native.cpp, blender.cpp, blender_native.cpp, blender_import.cpp,
// eevee.cpp, gl.cpp) whose doc block says what it is and its parameters and
// defaults.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "image/precision_bound.h"
#include "common/export_common.h"
#include "image/image.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace xval::renderers {

// xval's own version: the version of every built-in renderer that runs no
// outside tool.
inline constexpr const char* kXvalVersion = "xval 0.1.0";

// What a render needs besides the scene. The scene was checked against the
// command's budget when it was loaded (scene_file/scene_budget.h).
struct RenderRequest {
  // An outside tool's export, log and raw output go here: a fresh folder
  // the caller made (files/output_folder.h makeFreshFolder), or any folder
  // it owns. Unused by renderers that run no outside tool.
  std::filesystem::path work_dir;
  // Seconds before an outside tool is killed and the render fails.
  double timeout_seconds = kDefaultToolTimeoutSeconds;
  // The reference renderer's options; without them it renders the scene's
  // own settings (defaultOptions) on the exact double-precision path.
  std::optional<RenderOptions> options;
  // The scene's inputs key for the export cache (renderers/export_cache.h);
  // empty: the export is written, never cached.
  std::string export_key = {};
  // work_dir already holds the renderer's export (Renderer::exporter's
  // files, written there by the caller: renderers/job_export.h): the render
  // reads it and exports nothing.
  bool exported = false;
};

// What a render took.
struct RenderInfo {
  double seconds = 0.0;          // the whole render (an outside tool: its whole process)
  double render_seconds = -1.0;  // the render alone, as the tool reports it (-1: not reported)
  double parse_seconds = -1.0;   // reading the scene, as the tool reports it (-1: not reported)
  std::filesystem::path log;     // an outside tool's log (empty for none)
  RenderStats stats;             // the reference renderer's figures (default for the others)
};

// One scene prepared for drawing many frames (a real-time renderer's):
// draw() renders one whole frame and waits for it; the scene stays
// prepared while the FrameLoop lives. Call draw() and destroy the loop on
// the thread that prepared it.
struct FrameLoop {
  std::function<void()> draw;
  std::string device;          // what draws (for a GPU API: GL_RENDERER, GL_VERSION)
  double setup_seconds = 0.0;  // the preparation, once (context, shaders, uploads)
};

// One scene of a batch (Renderer::render_batch), and what became of it.
struct BatchItem {
  const Scene* scene = nullptr;
  RenderRequest request;
};
struct BatchOutcome {
  std::optional<Image> image;  // set when it rendered
  std::string error;           // else why not (as render's exception would say)
  RenderInfo info;
};
// Called with an item's index and its final outcome (Renderer::render_batch).
using BatchItemDone = std::function<void(size_t item, const BatchOutcome&)>;

// The export an outside renderer's render reads (its scene files), for a
// caller that decides the refusal by writing it into the work folder and
// hands it on to the render (RenderRequest::exported, renderers/
// job_export.h): a job exports its scene once.
struct RendererExport {
  // The exporter's name ("pov", "gltf"): renderers of one exporter share
  // the export cache's entries.
  std::string name;
  // Throws ExportError for what the harness refuses before it exports
  // (empty: nothing).
  std::function<void(const Scene&)> check;
  // Writes into `dir` exactly the files the render writes into its work
  // folder before running the tool; throws ExportError for what the
  // exporter refuses (a function of the scene alone).
  std::function<void(const Scene&, const std::filesystem::path& dir)> write;
  // The folder of the work folder the render reads the export from, as a
  // relative name ("gltf"); empty: the work folder itself.
  std::string folder;
};

// The coefficients of a job's estimated seconds on an idle core
// (validate/validation/job_cost.h: fixed + per_megasample x samples / 1e6 +
// per_megatriangle x triangles / 1e6), fitted to the job records of the
// reference set. Only the order they give matters.
struct JobCost {
  double fixed = 0.0, per_megasample = 0.0, per_megatriangle = 0.0;
};
// The reference renderer's (renderers/reference.cpp), and the cost of a
// renderer that declares none.
inline constexpr JobCost kReferenceJobCost{0.1, 2.5, 2.0};

struct Renderer {
  // How commands, file names and scene files name it: lower-case letters,
  // digits and '-' (it names files such as OUT/<scene>/<id>.exr).
  std::string id;
  // How listings and reports name it ("POV-Ray").
  std::string display_name;
  // As the subject of a sentence ("the reference renderer"); empty: the
  // display name.
  std::string subject;
  // One line: what it renders and how.
  std::string summary;
  // The renderer every other one is compared against (exactly one is).
  bool reference = false;
  // True: it renders every scene of the format, so `xval validate` renders
  // each scene with it and compares it with every other such renderer.
  // False: a check for a restricted class of scenes (restricted() below
  // when it is neither a geometry check nor a golden set): `xval validate`
  // renders exactly the scenes whose `renderers` field names it, and
  // `xval crosscheck --renderer ID` any scene.
  bool every_scene = true;
  // True: its image is geometry passes (render/geometry_passes.h), not a
  // render: crosscheck and validate compare it with the reference's passes
  // of the same scene (validate/geometry_check.h), not with any render; it
  // is in no image pair and in no attribution. validate runs it by default
  // (Registry::validateIds) as the case's geometry check
  // (validate/results/geometry_checks.h).
  bool geometry_passes = false;
  // The command printing the outside tool's version, e.g. {"povray",
  // "--version"}; its first word must be on PATH for the renderer to be
  // available. Empty: it runs no outside tool (version: kXvalVersion).
  std::vector<std::string> version_command;
  // The version is the first line of that command's output that contains
  // this ("POV-Ray") or the word "version".
  std::string version_marker;
  // Whatever else it needs that this machine lacks ("" when nothing is
  // missing), e.g. a script file. Optional.
  std::function<std::string()> missing;
  // Why it cannot express the scene exactly, "" when it can: the
  // exporter's refusal (ExportError), found without rendering. Optional
  // (absent: it can express every scene).
  std::function<std::string(const Scene&)> cannot_express;
  // The export its render reads (set for the renderers that export):
  // cannot_express must say what its check and write refuse (refusalOf).
  std::optional<RendererExport> exporter;
  // Renders the scene. Throws ExportError when it cannot express it,
  // ExternalToolError when an outside tool is missing, fails, hangs or
  // writes garbage, std::runtime_error otherwise; never returns a partial
  // image. `info` may be null.
  std::function<Image(const Scene&, const RenderRequest&, RenderInfo* info)> render;
  // Renders several scenes at once (for an outside tool: one process for
  // many scenes), each image the one `render` gives: one outcome per item,
  // in order; an item's failure is its own outcome's error, never another
  // item's. Optional (absent: scenes are rendered one at a time).
  // `item_done`, when not empty, is called once per item as soon as its
  // outcome is final, possibly while the others still render (so a caller
  // can use a scene's image before the batch ends), from one thread at a
  // time, never concurrently; the returned outcomes are the same.
  std::function<std::vector<BatchOutcome>(const std::vector<BatchItem>&, const BatchItemDone& item_done)> render_batch;
  // The share of a core one job keeps busy on average, measured (an outside
  // tool that mostly waits: below 1): the job pool runs up to 1 / cpu_share
  // such jobs per core beside each other (process/job_pool.h).
  double cpu_share = 1.0;
  // Its jobs' estimated cost, for validate's job order (JobCost).
  JobCost job_cost = kReferenceJobCost;
  // How far its arithmetic may put a pixel from the exact value, in steps
  // of the reference's probes (image/precision_bound.h): the comparison's
  // precision bound B_r(p). Each built-in renderer's file declares its own
  // with the basis (docs/precision-models.md); the default is a float32
  // GPU-like renderer's.
  PrecisionModel precision = float32Precision();
  // A real-time renderer's frame loop for `xval bench` (frames per second
  // of the frame alone, as the paper's Table 2). Optional (absent: bench
  // times whole renders). Throws as render does.
  std::function<FrameLoop(const Scene&)> prepare_frames;
  // A renderer defined by a file (renderers/renderer_file.h): that file,
  // absolute; empty for a built-in one. validate's plan records it with its
  // hash, so every job of the plan renders with the same definition.
  std::filesystem::path definition_file;
  // A golden set (renderers/golden.cpp): the id of the renderer whose
  // stored images it reads ("reference" for `golden`); empty for every
  // other renderer. A scene's \"renderers\" field that names that renderer
  // takes the set in its place (meantFor, registry.h).
  std::string images_of;

  // A renderer for the scenes that name it (a native tier: blender-native):
  // neither every scene's, nor a geometry check, nor a golden set.
  bool restricted() const { return !every_scene && !geometry_passes && images_of.empty(); }
  const std::string& sentenceSubject() const { return subject.empty() ? display_name : subject; }
  bool external() const { return !version_command.empty(); }
};

// For the renderer files: the exporter's refusal of a scene, found by
// exporting it into a temporary folder (removed again) without rendering:
// the ExportError's message, "" when `write_export` succeeds. Other errors
// (a full disk) propagate.
std::string exportRefusal(const std::function<void(const std::filesystem::path& dir)>& write_export);
// An export's refusal of a scene: its check's ExportError message, else
// its write's into a temporary folder (exportRefusal); "" when neither refuses.
std::string refusalOf(const RendererExport& ex, const Scene& scene);
// The golden-image renderers (renderers/golden.cpp): the stored set of
// the renderer `made_by` (id "golden" for the reference's, else
// "golden-<made_by>"); goldenAlias("golden:NAME") is that id ("" for an id
// not of that form); addGoldenSets adds golden-<id> for every registered
// renderer that is neither the reference nor a golden set.
class Registry;
Renderer goldenRendererOf(const std::string& made_by, const std::string& made_by_name);
// The id of the golden set of the renderer `made_by` (the one place of
// that rule).
std::string goldenSetIdOf(std::string_view made_by);
std::string goldenAlias(std::string_view id);
void addGoldenSets(Registry& registry);
// The command that stores renderer `made_by`'s image of `scene_file` in its
// golden set, as it runs pasted: the scene file absolute, every word
// shell-quoted (process/shell_word.h), and --renderer-file FILE when
// `made_by` is defined by a file (without it the renderer is unknown).
std::string goldenUpdateCommand(const std::filesystem::path& scene_file, const std::string& made_by);

// Whether `id` is of a golden set's form ("golden" or "golden-..."): ids
// xval defines only (a renderer file may not take one).
bool isGoldenSetId(std::string_view id);

// An outside tool's figures as a RenderInfo (nothing when `info` is null).
void setInfo(RenderInfo* info, const ExternalRenderInfo& tool);

}  // namespace xval::renderers
