// libFuzzer target: the tolerance file reader (loadTolerances,
// reference/tolerances.json or `xval validate --tolerances FILE`) on
// arbitrary bytes.
//
// Findings are crashes, sanitizer reports, time-outs, out-of-memory, any
// exception other than SceneError (file, field, value), and a table that
// loads with a tolerance outside its documented range.
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "fuzz_common.h"
#include "scene/json_reader.h"
#include "validate/tolerances.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path file = xval::fuzz::scratchDir() / "tolerances.json";
  xval::fuzz::writeFile(file, data, size);
  xval::ToleranceTable t;
  try {
    t = xval::loadTolerances(file);
  } catch (const xval::SceneError&) {
    return 0;
  }
  const xval::Tolerance& d = t.default_tolerance;
  if (!(d.max_abs >= 0.0 && std::isfinite(d.max_abs) && d.fraction >= 0.0 && d.fraction <= 1.0)) {
    std::fprintf(stderr, "loaded max_abs %g, fraction %g\n", d.max_abs, d.fraction);
    std::abort();
  }
  return 0;
}
