// libFuzzer target: `xval validate`'s job record reader (readRecord, the
// <scene>/<renderer>.job.json a job writes last) on arbitrary bytes.
//
// readRecord never throws: a record it cannot use has present = false and
// says why in `problem`. Findings are crashes, sanitizer reports,
// time-outs, out-of-memory, any exception, and a record that is both
// present and has a problem, or neither.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_common.h"
#include "validate/validation/job_record.h"

namespace v = xval::validation;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const v::Plan plan = [] {
    v::Plan p;
    p.dir = xval::fuzz::scratchDir();
    std::filesystem::create_directories(p.dir / "tiny");
    return p;
  }();
  v::RenderJob job;
  job.scene = "tiny";
  job.renderer = "reference";
  xval::fuzz::writeFile(plan.dir / job.record(), data, size);
  const v::JobRecord rec = v::readRecord(plan, job);
  if (rec.present == !rec.problem.empty()) {
    std::fprintf(stderr, "present = %d with problem \"%s\"\n", int(rec.present), rec.problem.c_str());
    std::abort();
  }
  return 0;
}
