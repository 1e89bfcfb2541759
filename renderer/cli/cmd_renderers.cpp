// xval renderers [--json]
//
// Lists every renderer of the registry (renderers/registry.h), in its
// order: id, display name, version, and whether it can render on this
// machine and, if not, why (an outside tool not on PATH, a failing
// `--version`, a missing script). Exit 0 (the listing is the answer, an
// unavailable renderer included).
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/renderer_file_option.h"
#include "renderers/registry.h"
#include "validate/validation/plan.h"

namespace xval::cli {

void addRenderersCommand(CLI::App& app, std::function<int()>& run) {
  auto json = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand(
      "renderers",
      "List the renderers (" + renderers::joinNames(renderers::registry().ids()) +
          "): id, name, version, its precision model (docs/precision-models.md), and whether each is available "
          "on this machine and, if not, why.");
  cmd->add_flag("--json", *json,
                "Print JSON instead: {\"renderers\": [{id, display_name, summary, reference, every_scene, "
                "geometry_passes, validate (run by `xval validate` by default on every scene it can take; a "
                "restricted renderer runs on the scenes that name it), precision {position_steps, uv_steps, "
                "normal_steps, relative, quantum_16bit, basis}, version, available, reason}]}");
  auto renderer_files = addRendererFileOption(cmd);
  cmd->callback([json, renderer_files, &run]() {
    run = [json, renderer_files]() -> int {
      renderers::registerRendererFiles(*renderer_files);
      const renderers::Registry& registry = renderers::registry();
      nlohmann::ordered_json out;
      out["renderers"] = nlohmann::ordered_json::array();
      for (const renderers::Renderer& r : registry.all()) {
        const renderers::Availability a = registry.availability(r.id);
        const std::string version = registry.version(r.id);
        if (*json) {
          out["renderers"].push_back({{"id", r.id},
                                      {"display_name", r.display_name},
                                      {"summary", r.summary},
                                      {"reference", r.reference},
                                      {"every_scene", r.every_scene},
                                      {"geometry_passes", r.geometry_passes},
                                      {"validate", r.every_scene || r.geometry_passes},
                                      {"precision", precisionJson(renderers::precisionOf(r))},
                                      {"version", version},
                                      {"available", a.available},
                                      {"reason", a.reason}});
          continue;
        }
        std::printf("%-16s %-24s %s\n", r.id.c_str(), r.display_name.c_str(), r.summary.c_str());
        std::printf("%-16s version: %s\n", "", version.c_str());
        if (!r.geometry_passes) {
          const PrecisionModel& p = renderers::precisionOf(r);
          std::printf("%-16s precision: %g position, %g uv, %g normal steps, relative %g, quantum %g/65535 (%s)\n", "",
                      p.position_steps, p.uv_steps, p.normal_steps, p.relative, p.quantum_16bit, p.basis.c_str());
        }
        std::printf("%-16s %s%s%s\n", "", a.available ? "available" : "UNAVAILABLE: ", a.reason.c_str(),
                    r.reference      ? " (the reference: every other renderer is compared with it)"
                    : r.every_scene ? ""
                    : r.geometry_passes
                        ? " (a geometry check: validate runs it on the scenes it can take, against the reference's passes)"
                    : r.restricted()
                        ? " (for the scenes that name it: validate runs it on the scenes whose `renderers` field names "
                          "it; crosscheck and render take any scene)"
                    : validation::runsWhenNamed(r.id)
                        ? " (validate runs it only when --renderers names it; crosscheck and render take it)"
                        : " (for some scenes only: crosscheck and render, not validate)");
      }
      if (*json) std::printf("%s\n", out.dump(2).c_str());
      return 0;
    };
  });
}

}  // namespace xval::cli
