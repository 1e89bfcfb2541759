// A case's verdict (validate/results/case_verdict.h): decided on what
// the case compared; a case that compared nothing is never a pass.
#include <gtest/gtest.h>

#include <stdexcept>

#include "validate/results/case_verdict.h"

using namespace xval::validation;

TEST(CaseVerdict, NothingComparedIsNeverAPass) {
  EXPECT_EQ(caseVerdict({}), CaseVerdict::NotCompared);
  EXPECT_EQ(caseVerdict({0, 0, 1}), CaseVerdict::Pass);
  EXPECT_EQ(caseVerdict({0, 1, 3}), CaseVerdict::Fail);
  EXPECT_EQ(caseVerdict({0, 1, 0}), CaseVerdict::Fail);
  // An error outweighs everything: a render failed, so its pairs are unknown.
  EXPECT_EQ(caseVerdict({1, 0, 0}), CaseVerdict::Error);
  EXPECT_EQ(caseVerdict({1, 1, 1}), CaseVerdict::Error);
}

TEST(CaseVerdict, ExitStatusOfTheRun) {
  EXPECT_EQ(validateExitStatus({CaseVerdict::Pass, CaseVerdict::Pass}), 0);
  EXPECT_EQ(validateExitStatus({CaseVerdict::Pass, CaseVerdict::NotCompared}), 1);
  EXPECT_EQ(validateExitStatus({CaseVerdict::Fail, CaseVerdict::NotCompared}), 1);
  EXPECT_EQ(validateExitStatus({CaseVerdict::Fail, CaseVerdict::Error, CaseVerdict::NotCompared}), 2);
}

TEST(CaseVerdict, WordsRoundTripAndAnotherWordIsAnErrorNamingWhere) {
  for (CaseVerdict v : {CaseVerdict::Pass, CaseVerdict::Fail, CaseVerdict::Error, CaseVerdict::NotCompared})
    EXPECT_EQ(parseCaseVerdict(verdictName(v), "x"), v);
  EXPECT_STREQ(verdictName(CaseVerdict::NotCompared), "not_compared");
  try {
    parseCaseVerdict("not expressible", "results.json: case a: verdict");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(),
                 "results.json: case a: verdict: \"not expressible\": expected pass, fail, error or not_compared");
  }
}
