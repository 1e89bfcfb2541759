// runProcess: a time-out is reported with the digits it was given. runForked:
// what the child writes comes back, and its crash, exception or hang is its own.
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

// runForked: the work's output comes back; a crash, an exception, a hang
// and an oversized output are each the child's failure, and this process
// goes on.
TEST(RunForked, OutputComesBack) {
  const std::string text(200000, 'x');  // more than a pipe holds
  const ForkedResult f = runForked([&] { return text; }, 30, 1 << 20);
  ASSERT_TRUE(f.process.ok()) << f.process.describe() << "\n" << f.diagnostics;
  EXPECT_EQ(f.output, text);
}

TEST(RunForked, CrashIsTheChildsSignal) {
  const ForkedResult f = runForked([]() -> std::string {
    std::fputs("about to crash\n", stderr);
    raise(SIGSEGV);
    return "not reached";
  }, 30, 1024);
  EXPECT_FALSE(f.process.ok());
  EXPECT_EQ(f.process.signal, SIGSEGV) << f.process.describe();
  EXPECT_EQ(f.summary(), "about to crash");
  EXPECT_TRUE(f.output.empty());
}

TEST(RunForked, ExceptionIsExitCode70WithItsMessage) {
  const ForkedResult f = runForked([]() -> std::string { throw std::runtime_error("the reader gave up"); }, 30, 1024);
  EXPECT_EQ(f.process.exit_code, 70) << f.process.describe();
  EXPECT_EQ(f.summary(), "exception: the reader gave up");
}

TEST(RunForked, HangIsKilledAtTheTimeOut) {
  const ForkedResult f = runForked([]() -> std::string { for (;;) pause(); }, 0.2, 1024);
  EXPECT_TRUE(f.process.timed_out);
  EXPECT_LT(f.process.seconds, 10.0);
  EXPECT_EQ(f.process.describe(), "timed out after 0.2 s and was killed");
}

TEST(RunForked, OversizedOutputIsNotRead) {
  const ForkedResult f = runForked([] { return std::string(5000, 'y'); }, 30, 4096);
  EXPECT_EQ(f.process.exit_code, 71);
  EXPECT_TRUE(f.output.empty());
  EXPECT_NE(f.diagnostics.find("the child's output is 5000 bytes; the limit is 4096"), std::string::npos)
      << f.diagnostics;
}
