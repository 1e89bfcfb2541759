// libFuzzer target: `xval validate`'s plan reader (readPlan, the jobs.json
// a cluster run hands to every job) on arbitrary bytes.
//
// Findings are crashes, sanitizer reports, time-outs, out-of-memory, and
// any exception that is not a std::runtime_error (readPlan's errors, which
// name the file and the field). A plan that reads must survive the writer:
// writePlan then readPlan gives the same plan.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "fuzz_common.h"
#include "validate/validation/plan.h"

namespace v = xval::validation;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path file = xval::fuzz::scratchDir() / "jobs.json";
  xval::fuzz::writeFile(file, data, size);
  v::Plan plan;
  try {
    plan = v::readPlan(file);
  } catch (const std::runtime_error&) {
    return 0;
  }
  v::writePlan(plan);
  const v::Plan again = v::readPlan(file);
  bool same = again.dir == plan.dir && again.tolerances == plan.tolerances &&
              again.tolerances_path == plan.tolerances_path && again.timeout_seconds == plan.timeout_seconds &&
              again.created_unix == plan.created_unix && again.jobs.size() == plan.jobs.size();
  for (size_t k = 0; same && k < plan.jobs.size(); ++k) {
    const v::RenderJob &a = plan.jobs[k], &b = again.jobs[k];
    same = a.index == b.index && a.scene == b.scene && a.file == b.file && a.path == b.path &&
           a.renderer == b.renderer && a.input_hash == b.input_hash;
  }
  if (!same) {
    std::fprintf(stderr, "the plan read back differs from the one written\n");
    std::abort();
  }
  return 0;
}
