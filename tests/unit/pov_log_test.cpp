// The timings read from POV-Ray 3.7's log (povray/pov_log.h).
#include "povray/pov_log.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace {

using xval::povLogTimes;

// A log written by this machine's `povray` 3.7.0.10 for a 32x32 scene of
// 20000 small spheres made by a #while loop (tests/unit/pov_logs/).
std::string realLog() {
  std::ifstream in(XVAL_TESTS_DIR "/unit/pov_logs/sphere_grid.log", std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  EXPECT_FALSE(s.str().empty()) << "the fixture sphere_grid.log is missing";
  return s.str();
}

TEST(PovLog, RealLogGivesEachBlocksWallTime) {
  const xval::PovLogTimes t = povLogTimes(realLog());
  EXPECT_DOUBLE_EQ(t.parse_seconds, 0.186);
  EXPECT_DOUBLE_EQ(t.bounding_seconds, 0.043);
  EXPECT_DOUBLE_EQ(t.trace_seconds, 0.002);
  EXPECT_EQ(t.photon_seconds, -1.0);  // "No photons": absent, not 0
}

TEST(PovLog, LogCutBeforeTheRenderBlockHasParseButNoTrace) {
  const std::string log = realLog();
  const size_t cut = log.find("Render Time:");
  ASSERT_NE(cut, std::string::npos);
  const xval::PovLogTimes t = povLogTimes(log.substr(0, cut));
  EXPECT_DOUBLE_EQ(t.parse_seconds, 0.186);
  EXPECT_EQ(t.trace_seconds, -1.0);
}

TEST(PovLog, LineCutInsideTheFigureIsAbsent) {
  const std::string log = realLog();
  const size_t cut = log.find("(0.002");
  ASSERT_NE(cut, std::string::npos);
  EXPECT_EQ(povLogTimes(log.substr(0, cut + 4)).trace_seconds, -1.0);
}

TEST(PovLog, GarbageFiguresAreAbsentNeverZero) {
  const xval::PovLogTimes t = povLogTimes(
      "  Parse Time:       0 hours  0 minutes  0 seconds (nan seconds)\n"
      "  Bounding Time:    0 hours  0 minutes  0 seconds (-0.5 seconds)\n"
      "  Photon Time:      0 hours  0 minutes  0 seconds (0.1x seconds)\n"
      "  Trace Time:       0 hours  0 minutes  0 seconds (seconds)\n");
  EXPECT_EQ(t.parse_seconds, -1.0);
  EXPECT_EQ(t.bounding_seconds, -1.0);
  EXPECT_EQ(t.photon_seconds, -1.0);
  EXPECT_EQ(t.trace_seconds, -1.0);
  const xval::PovLogTimes none = povLogTimes("\x01\xff garbage (1.0 seconds)\n");
  EXPECT_EQ(none.parse_seconds, -1.0);
  EXPECT_EQ(none.trace_seconds, -1.0);
}

TEST(PovLog, CarriageReturnsAndAMissingFileAreHandled) {
  EXPECT_DOUBLE_EQ(povLogTimes("  Trace Time: 0 hours 0 minutes 1 seconds (1.250 seconds)\r\n").trace_seconds, 1.25);
  EXPECT_EQ(xval::povLogTimesOfFile("/nonexistent/povray.log").parse_seconds, -1.0);
}

}  // namespace
