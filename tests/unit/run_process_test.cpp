// runProcess: a time-out is reported with the digits it was given. runCaptured:
// what the program writes comes back, and its crash, failure or hang is its own.
#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "process/run_process.h"
#include "support/temp_files.h"

using namespace xval;

TEST(RunProcess, SubSecondTimeOutIsReportedAsGiven) {
  const auto dir = xval::test::freshTempDir("xval_run_process_test");
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

// runCaptured: the program's output comes back; a crash, a failure, a hang
// and an oversized output are each the program's, and this process goes
// on. The programs are /bin/sh scripts (no shell runs them otherwise).
TEST(RunCaptured, OutputComesBack) {
  // More than a pipe holds: 200,000 bytes.
  const CapturedResult f = runCaptured({"/bin/sh", "-c", "head -c 200000 /dev/zero | tr '\\0' x"}, 30, 1 << 20);
  ASSERT_TRUE(f.process.ok()) << f.process.describe() << "\n" << f.diagnostics;
  EXPECT_EQ(f.output, std::string(200000, 'x'));
}

TEST(RunCaptured, CrashIsTheProgramsSignal) {
  const CapturedResult f = runCaptured({"/bin/sh", "-c", "echo about to crash >&2; kill -SEGV $$"}, 30, 1024);
  EXPECT_FALSE(f.process.ok());
  EXPECT_EQ(f.process.signal, SIGSEGV) << f.process.describe();
  EXPECT_EQ(f.summary(), "about to crash");
  EXPECT_TRUE(f.output.empty());
}

TEST(RunCaptured, FailureIsItsExitCodeWithItsLastLine) {
  const CapturedResult f =
      runCaptured({"/bin/sh", "-c", "echo partial; echo first >&2; echo 'exception: the reader gave up' >&2; exit 70"},
                  30, 1024);
  EXPECT_EQ(f.process.exit_code, 70) << f.process.describe();
  EXPECT_EQ(f.summary(), "exception: the reader gave up");
  EXPECT_TRUE(f.output.empty());  // what a failed program wrote is not taken
}

TEST(RunCaptured, HangIsKilledAtTheTimeOutWithItsGroup) {
  // The script's own child (sleep) is in its group and goes with it.
  const CapturedResult f = runCaptured({"/bin/sh", "-c", "sleep 30; echo done"}, 0.2, 1024);
  EXPECT_TRUE(f.process.timed_out);
  EXPECT_LT(f.process.seconds, 10.0);
  EXPECT_EQ(f.process.describe(), "timed out after 0.2 s and was killed");
}

TEST(RunCaptured, OversizedOutputIsNotRead) {
  const CapturedResult f = runCaptured({"/bin/sh", "-c", "head -c 5000 /dev/zero"}, 30, 4096);
  EXPECT_EQ(f.process.exit_code, 71);
  EXPECT_TRUE(f.output.empty());
  EXPECT_NE(f.diagnostics.find("its output is 5000 bytes; the limit is 4096"), std::string::npos) << f.diagnostics;
}

TEST(RunCaptured, AMissingProgramDoesNotStart) {
  const CapturedResult f = runCaptured({"/nonexistent/xval-model-reader", "x"}, 30, 1024);
  EXPECT_FALSE(f.process.started);
  EXPECT_NE(f.process.describe().find("/nonexistent/xval-model-reader: No such file or directory"), std::string::npos)
      << f.process.describe();
}
