// runProcess: a time-out is reported with the digits it was given.
#include <gtest/gtest.h>

#include <filesystem>

#include "process/run_process.h"

using namespace xval;

TEST(RunProcess, SubSecondTimeOutIsReportedAsGiven) {
  const auto dir = std::filesystem::temp_directory_path() / "xval_run_process_test";
  std::filesystem::create_directories(dir);
  ProcessResult r = runProcess({"sleep", "20"}, dir, dir / "sleep.log", 0.3);
  ASSERT_TRUE(r.started) << r.error;
  EXPECT_TRUE(r.timed_out);
  EXPECT_LT(r.seconds, 10.0);
  EXPECT_EQ(r.describe(), "timed out after 0.3 s and was killed");
  std::filesystem::remove_all(dir);
}

TEST(RunProcess, WholeSecondTimeOutHasNoFraction) {
  ProcessResult r;
  r.started = true, r.timed_out = true, r.timeout_seconds = 600, r.seconds = 600.04;
  EXPECT_EQ(r.describe(), "timed out after 600 s and was killed");
}
