// results.json of `xval validate` (results_file.h).
#include "validate/validation/results_file.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>

#include <fmt/format.h>

#include "renderers/registry.h"
#include "validate/common/provenance.h"
#include "validate/paper_claims.h"
#include "validate/validation/file_fields.h"

namespace xval::validation {

namespace {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;

// FNV-1a over the bytes of the files that define the run's settings
// (results.json provenance.settings_hash; unchanged from the single-process
// validate so published hashes stay comparable).
std::string settingsHash(const std::vector<fs::path>& files) {
  uint64_t h = 1469598103934665603ull;
  for (const auto& f : files) {
    std::string bytes = readBytes(f);
    bytes += f.filename().string();
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  }
  return fmt::format("{:016x}", h);
}

J provenanceJson(const Plan& plan, const std::vector<fs::path>& setting_files) {
  J p = J::object();
  // The versions of the outside tools the run used (probed with a
  // time-out, renderers/registry.h): those of its renderers, geometry
  // checks (blender-import: Blender's) and users' renderers included, in
  // the run's order; a renderer the run did not use is not listed.
  for (const std::string& id : plan.renderers)
    if (const renderers::Renderer& r = renderers::registry().at(id); r.external())
      p[r.id] = renderers::registry().version(r.id);
  // The one provenance record (validate/common/provenance.h): the compiler
  // that built this xval, the commit (with -dirty) it ran in.
  const Provenance prov = collectProvenance(plan.dir / "version.log");
  p["openexr"] = prov.openexr;
  p["libpng"] = prov.libpng;
  p["openimageio"] = prov.openimageio;
  p["compiler"] = prov.compiler;
  p["tolerances"] = plan.tolerances;
  p["git_commit"] = prov.git_commit;
  p["settings_hash"] = settingsHash(setting_files);
  return p;
}

}  // namespace

J resultsJson(const Plan& plan, const J& cases, const std::vector<fs::path>& setting_files, const J& sections) {
  J results;
  results["format"] = "xval-results/1";
  results["provenance"] = provenanceJson(plan, setting_files);
  // From the plan's making to now: on a cluster this includes the time the
  // jobs waited in the queue.
  results["wall_seconds"] = std::max(0.0, nowUnix() - plan.created_unix);
  results["renderers"] = plan.renderers;  // the run's (validate --renderers, else Registry::validateIds)
  results["cases"] = cases;
  if (J claims = paperClaims(cases); !claims.is_null()) results["paper_claims"] = claims;
  if (!sections.empty()) results["sections"] = sections;
  return results;
}

}  // namespace xval::validation
