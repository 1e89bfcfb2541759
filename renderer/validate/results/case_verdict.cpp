// A case's verdict (case_verdict.h).
#include "validate/results/case_verdict.h"

#include <algorithm>
#include <stdexcept>

namespace xval::validation {

namespace {

constexpr CaseVerdict kAll[] = {CaseVerdict::Pass, CaseVerdict::Fail, CaseVerdict::Error, CaseVerdict::NotCompared};

}  // namespace

CaseVerdict caseVerdict(const CaseTally& t) {
  if (t.errors > 0) return CaseVerdict::Error;
  if (t.failed > 0) return CaseVerdict::Fail;
  return t.passed > 0 ? CaseVerdict::Pass : CaseVerdict::NotCompared;
}

const char* verdictName(CaseVerdict v) {
  switch (v) {
    case CaseVerdict::Pass: return "pass";
    case CaseVerdict::Fail: return "fail";
    case CaseVerdict::Error: return "error";
    case CaseVerdict::NotCompared: return "not_compared";
  }
  throw std::logic_error("verdictName: not a CaseVerdict");
}

CaseVerdict parseCaseVerdict(const std::string& word, const std::string& where) {
  for (CaseVerdict v : kAll)
    if (word == verdictName(v)) return v;
  throw std::runtime_error(where + ": \"" + word + "\": expected pass, fail, error or not_compared");
}

int validateExitStatus(const std::vector<CaseVerdict>& cases) {
  const auto any = [&](CaseVerdict v) { return std::find(cases.begin(), cases.end(), v) != cases.end(); };
  if (any(CaseVerdict::Error)) return 2;
  return any(CaseVerdict::Fail) || any(CaseVerdict::NotCompared) ? 1 : 0;
}

}  // namespace xval::validation
