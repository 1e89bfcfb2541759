// A case's verdict in `xval validate` (results.json cases[].verdict,
// docs/results-schema.json): decided once, by the compare step
// (compare_step.h), from what the case compared; the console summary, the
// exit status, results.json's `pass`, JUnit (validate/report/junit_report.h), the
// next steps and the report (validate/report/report.h) all read it, none decides
// it again.
//
//   error         a render of the case has an error (it failed, its job has
//                 no usable record, its EXR cannot be read), so an image
//                 pair or a geometry check could not be compared;
//   fail          no error, and an image pair outside its tolerance or a
//                 geometry check outside its bounds;
//   not_compared  no error and nothing compared: no image pair and no
//                 geometry check was compared (the scene's `renderers`
//                 field or --renderers left all renderers but one out, or
//                 the others cannot express the scene). Never a pass:
//                 nothing was validated;
//   pass          something compared, and everything compared passes (a
//                 pair or check whose renderer cannot express the scene is
//                 no failure).
// Exit status of the run (validateExitStatus): 2 when a case is an error,
// else 1 when a case fails or compared nothing, else 0.
#pragma once

#include <string>
#include <vector>

namespace xval::validation {

enum class CaseVerdict { Pass, Fail, Error, NotCompared };

// What one case compared, counted.
struct CaseTally {
  int errors = 0;  // renders with an error; pairs and geometry checks not compared for one
  int failed = 0;  // image pairs outside their tolerance, geometry checks outside their bounds
  int passed = 0;  // image pairs within their tolerance, geometry checks within their bounds
};

CaseVerdict caseVerdict(const CaseTally& t);

// results.json's word: "pass", "fail", "error", "not_compared".
const char* verdictName(CaseVerdict v);
// The verdict of that word; throws std::runtime_error naming `where` and
// the words expected for any other.
CaseVerdict parseCaseVerdict(const std::string& word, const std::string& where);

// The exit status of `xval validate` for its cases' verdicts (see above).
int validateExitStatus(const std::vector<CaseVerdict>& cases);

}  // namespace xval::validation
