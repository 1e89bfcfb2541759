// xval render SCENE.json -o OUT.exr [--spp N] [--precision float|double] [--renderer ID]
#include <cstdio>
#include <map>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/renderer_file_option.h"
#include "geometry/scene_meshes.h"
#include "render/renderer.h"
#include "renderers/registry.h"
#include "lint/scene_lint.h"
#include "scene_file/scene_loader.h"

namespace xval::cli {

namespace {
struct RenderArgs {
  std::string scene, output;
  int spp = 0;
  BudgetOptions budget;
  std::string precision;
  int threads = 0;
  bool quiet = false, no_diagnostics = false, keep_back_faces = false;
  std::string visibility = "auto";
  std::string renderer;  // default: the registry's reference
  std::string work_dir;
  std::string stats;
  double timeout = kDefaultToolTimeoutSeconds;
};
}  // namespace

void addRenderCommand(CLI::App& app, std::function<int()>& run) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Render a scene with one renderer: --renderer, by default the reference renderer (ray caster, "
      "local illumination, no shadows).\nWrites OpenEXR (32-bit float RGBA: the model's output, each "
      "sample saturated to [0,1],\nbox-filtered, premultiplied by alpha = hit coverage; the reference "
      "renderer adds raw.R/G/B = the unsaturated\nmodel colour and diagnostic channels) or, for a .png "
      "output, a 16-bit RGBA PNG of the same values\n(alpha = coverage, colour unassociated). No "
      "transfer function is applied anywhere:\nthe values are display-referred codes, like the texture "
      "codes the model reads (docs/scene-format.md,\n\"output encoding\"; a viewer that takes an EXR as "
      "linear shows them too bright).");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->output, "Output image: .exr or .png")->required();
  cmd->add_option("--spp", args->spp,
                  "Samples per pixel, a perfect square 1..256 (n x n stratified grid, box "
                  "filter); default: the scene's render.spp")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--precision", args->precision,
                  "float (the fast path: float shading, visibility rasterised or traced as Embree "
                  "float packets) or double (the exact reference path: double-precision "
                  "watertight ray test and shading); default: the scene's render.precision. "
                  "Both skip back faces of closed meshes seen from outside (never a first hit)")
      ->check(CLI::IsMember({"float", "double"}));
  cmd->add_option("--visibility", args->visibility,
                  "float path only: auto (rasterise when the whole scene is in front of the "
                  "camera, else Embree packets; default) or rays (always Embree packets)")
      ->check(CLI::IsMember({"auto", "rays"}));
  cmd->add_flag("--no-diagnostics", args->no_diagnostics,
                "Do not compute the EXR's diagnostic channels (raw, Z, backfacing, incidence, "
                "albedo, texel_edge, triangle_edge and the precision probes: edge_fraction, "
                "backfacing_flip, precision.*); in float the hits are then shaded by the SIMD kernel where it covers the "
                "scene (same pixels)");
  cmd->add_flag("--keep-back-faces", args->keep_back_faces,
                "Do not skip the back faces of closed meshes seen from outside (the image is the "
                "same; for checking that)");
  cmd->add_option("--threads", args->threads, "Worker threads (default: all hardware threads)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("-q,--quiet", args->quiet, "No progress or summary on stderr");
  const renderers::Registry& registry = renderers::registry();
  args->renderer = registry.reference().id;
  cmd->add_option("--renderer", args->renderer,
                  "One of " + renderers::joinNames(registry.ids()) + " (default " + registry.reference().id +
                      "; xval renderers lists them): an external renderer is exported to, run with a "
                      "time-out, and its image written like the reference's (the model's output saturated "
                      "to [0,1], no transfer function; alpha = coverage) without the diagnostic channels");
  auto renderer_files = addRendererFileOption(cmd);
  cmd->add_option("--work-dir", args->work_dir,
                  "Folder for an external renderer's export, log and raw output (default: "
                  "OUT's folder/OUT-stem.RENDERER)");
  cmd->add_option("--stats", args->stats,
                  "Also write what was rendered and how long it took to this JSON file (reference "
                  "renderer: width, height, spp, precision, visibility, culled_triangles, shading, "
                  "setup_s, frame_s, edge_fraction_s: the part of frame_s the diagnostics' edge-fraction pass took; "
                  "external: renderer, width, height, process_s)");
  cmd->add_option("--timeout", args->timeout,
                  "Seconds before an external renderer is killed and the render fails (default 600)")
      ->check(Seconds);
  addBudgetOptions(cmd, args->budget);
  cmd->callback([args, renderer_files, &run]() {
    run = [args, renderer_files]() {
      renderers::registerRendererFiles(*renderer_files);
      Scene scene = loadScene(args->scene, args->budget.get());
      printSceneWarnings("xval render", scene);
      for (const std::string& n : meshNotes(scene)) std::fprintf(stderr, "xval render: note: %s\n", n.c_str());
      RenderOptions opt = defaultOptions(scene);
      if (args->spp) {
        requirePerfectSquareSpp(args->spp, "--spp");
        opt.spp = args->spp;
        checkBudget(scene, opt.spp, args->budget.get());
      }
      if (!args->precision.empty())
        opt.precision = args->precision == "float" ? Precision::Float : Precision::Double;
      opt.threads = args->threads;
      opt.progress = !args->quiet;
      opt.diagnostics = !args->no_diagnostics;
      opt.cull_back_faces = !args->keep_back_faces;
      if (args->visibility != "auto" && opt.precision != Precision::Float)
        throw std::runtime_error("--visibility " + args->visibility +
                                 ": applies to the float path only (--precision float)");
      opt.rasterise = args->visibility == "auto";
      const renderers::Renderer& renderer = renderers::registry().at(args->renderer);
      if (!renderer.reference) {
        if (args->spp || !args->precision.empty())
          throw std::runtime_error("--spp and --precision apply to the reference renderer only");
        std::filesystem::path out(args->output);
        std::filesystem::path work = args->work_dir.empty()
            ? out.parent_path() / (out.stem().string() + "." + args->renderer)
            : std::filesystem::path(args->work_dir);
        renderers::RenderInfo info;
        Image img = renderer.render(scene, {work, args->timeout, {}}, &info);
        writeImage(img, out);
        if (!args->stats.empty())
          writeJsonFile(args->stats, {{"scene", scene.name}, {"renderer", args->renderer},
                                      {"width", img.width}, {"height", img.height},
                                      {"process_s", info.seconds}});
        if (!args->quiet)
          std::fprintf(stderr, "xval render: wrote %s (%s, %dx%d): %.3f s (whole process), work dir %s\n",
                       args->output.c_str(), args->renderer.c_str(), img.width, img.height,
                       info.seconds, work.c_str());
        return 0;
      }
      renderers::RenderInfo info;
      Image img = renderer.render(scene, {{}, args->timeout, opt}, &info);
      const RenderStats& stats = info.stats;
      writeImage(img, args->output);
      if (!args->stats.empty())
        writeJsonFile(args->stats,
                      {{"scene", scene.name}, {"renderer", renderer.id}, {"width", img.width},
                       {"height", img.height}, {"spp", opt.spp}, {"precision", toString(opt.precision)},
                       {"visibility", stats.visibility}, {"culled_triangles", stats.culled_triangles},
                       {"shading", stats.shading}, {"setup_s", stats.setup_seconds},
                       {"frame_s", stats.trace_seconds}, {"edge_fraction_s", stats.edge_fraction_seconds}});
      if (!args->quiet)
        std::fprintf(stderr,
                     "xval render: wrote %s (%dx%d, %d spp, %s, visibility: %s): setup %.3f s, "
                     "frame %.3f s (of which the edge-fraction pass %.3f s)\n",
                     args->output.c_str(), img.width, img.height, opt.spp, toString(opt.precision),
                     describeVisibility(stats).c_str(), stats.setup_seconds, stats.trace_seconds,
                     stats.edge_fraction_seconds);
      return 0;
    };
  });
}

}  // namespace xval::cli
