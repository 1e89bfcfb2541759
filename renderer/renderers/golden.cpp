// golden, golden-NAME: a stored set of golden images as a renderer
// (golden/golden_set.h). `golden` is the reference renderer's set;
// `golden-NAME` (also spelled golden:NAME) the set another renderer NAME
// stored with `xval golden update --renderer NAME`.
//
// "Rendering" a scene reads its stored image from the folder `golden/NAME`
// beside the scene file's folder. It refuses, with the reason, a scene
// without a stored image, a scene file whose SHA-256 differs from the one
// stored with the image (the scene changed: the image no longer shows it),
// an image file that changed, one of another size than the scene's, or one
// holding NaN or infinite values. A scene the renderer that made the set
// cannot express (its cannot_express) is not expressible by the set either,
// with that reason: there is no image to store, and `xval golden update`
// would refuse it, so the missing image's hint would not run as printed. Runs no outside tool (no work folder, no
// time-out); its version is xval's, the stored renderer's version is in the
// manifest.
//
// Not an every-scene renderer: `xval validate` renders it only when named
// (a scene set may have no golden images); crosscheck and render take it
// like any other.
#include "golden/golden_set.h"
#include "renderers/renderer.h"

#include <chrono>
#include <utility>
#include <vector>

#include "process/shell_word.h"
#include "renderers/registry.h"

namespace xval::renderers {

std::string goldenSetIdOf(std::string_view made_by) {
  return made_by == "reference" ? std::string("golden") : "golden-" + std::string(made_by);
}

Renderer goldenRendererOf(const std::string& made_by, const std::string& made_by_name) {
  Renderer r;
  const bool reference = made_by == "reference";
  r.id = goldenSetIdOf(made_by);
  r.display_name = reference ? "golden" : "golden (" + made_by_name + ")";
  r.subject = reference ? "the golden images" : "the golden images of " + made_by_name;
  r.summary = "the images " + made_by_name + " stored beside the scene set (golden/" + made_by +
              "/, xval golden update); refuses a scene file changed since";
  r.every_scene = false;
  r.images_of = made_by;
  r.cannot_express = [made_by, made_by_name](const Scene& scene) -> std::string {
    const Renderer* maker = registry().find(made_by);
    if (!maker || !maker->cannot_express) return "";
    const std::string why = maker->cannot_express(scene);
    return why.empty() ? "" : made_by_name + " cannot express the scene, so its golden set has no image of it: " + why;
  };
  r.render = [made_by](const Scene& scene, const RenderRequest&, RenderInfo* info) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::filesystem::path folder = golden::goldenFolder(scene.source_file, made_by);
    const golden::Manifest m = golden::readManifest(folder, made_by);
    if (const std::string problem = golden::goldenProblem(folder, m, scene.source_file,
                                                            goldenUpdateCommand(scene.source_file, made_by)); !problem.empty())
      throw std::runtime_error("golden images of " + made_by + ": " + problem);
    const golden::Entry& e = m.entries.at(scene.source_file.stem().string());
    Image image = readImage(folder / e.image, scene.camera.width, scene.camera.height);
    requireFinite("golden image " + (folder / e.image).string(), image);
    if (info) info->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return image;
  };
  return r;
}

Renderer goldenRenderer() { return goldenRendererOf("reference", "the reference renderer"); }

std::string goldenUpdateCommand(const std::filesystem::path& scene_file, const std::string& made_by) {
  std::string c = "xval golden update " + shellPath(scene_file) +
                  " --renderer " + shellWord(made_by);
  if (const Renderer* r = registry().find(made_by); r && !r->definition_file.empty())
    c += " --renderer-file " + shellPath(r->definition_file);
  return c;
}

std::string goldenAlias(std::string_view id) {
  constexpr std::string_view prefix = "golden:";
  if (id.substr(0, prefix.size()) != prefix) return "";
  return goldenSetIdOf(id.substr(prefix.size()));
}

bool isGoldenSetId(std::string_view id) { return id == "golden" || id.substr(0, 7) == "golden-"; }

void addGoldenSets(Registry& registry) {
  std::vector<std::pair<std::string, std::string>> sources;
  for (const Renderer& r : registry.all())
    if (!r.reference && !r.geometry_passes && !isGoldenSetId(r.id)) sources.emplace_back(r.id, r.display_name);
  for (const auto& [id, name] : sources)
    if (!registry.find(goldenSetIdOf(id))) registry.add(goldenRendererOf(id, name));
}

}  // namespace xval::renderers
