// validate/common/frame_timing.h: how many frames are rendered and timed
// under each budget, and spread().
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "validate/common/frame_timing.h"

using namespace xval;

TEST(FrameTiming, FixedFrameCountWithoutTimeLimit) {
  int calls = 0;
  FrameTimes t = timeFrames([&] { ++calls; }, FrameBudget{5}, WarmUp::AlreadyDone);
  EXPECT_EQ(calls, 5);
  EXPECT_EQ(t.wall_s.size(), 5u);
  EXPECT_EQ(t.cpu_s.size(), 5u);
  EXPECT_FALSE(t.warmup_frame_timed);
  calls = 0;
  t = timeFrames([&] { ++calls; }, FrameBudget{5}, WarmUp::Render);
  EXPECT_EQ(calls, 6);  // one warm-up, not counted
  EXPECT_EQ(t.wall_s.size(), 5u);
  EXPECT_FALSE(t.warmup_frame_timed);
}

// A warm-up frame that alone takes max_seconds is the one timed frame.
TEST(FrameTiming, LongWarmUpIsTheOneTimedFrame) {
  int calls = 0;
  auto slow = [&] {
    ++calls;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  };
  FrameTimes t = timeFrames(slow, FrameBudget{5, 0.001}, WarmUp::Render);
  EXPECT_EQ(calls, 1);
  ASSERT_EQ(t.wall_s.size(), 1u);
  EXPECT_TRUE(t.warmup_frame_timed);
  EXPECT_GE(t.wall_s[0], 0.004);
  // Without a warm-up here: at least one frame is still timed.
  calls = 0;
  t = timeFrames(slow, FrameBudget{5, 0.001}, WarmUp::AlreadyDone);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(t.wall_s.size(), 1u);
  EXPECT_FALSE(t.warmup_frame_timed);
}

// Timing stops once the timed frames add up to max_seconds: every frame
// but the last started with the sum below it, and the last made it reach
// it unless the frame count ran out first.
TEST(FrameTiming, StopsAtTheTimeBudget) {
  int calls = 0;
  auto frame = [&] {
    ++calls;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  };
  const FrameBudget budget{100, 0.05};
  const FrameTimes t = timeFrames(frame, budget, WarmUp::AlreadyDone);
  ASSERT_GE(t.wall_s.size(), 1u);
  EXPECT_LT(t.wall_s.size(), 100u);  // 20 ms frames: far fewer than 100 fit in 50 ms
  EXPECT_EQ(size_t(calls), t.wall_s.size());
  double before_last = 0;
  for (size_t i = 0; i + 1 < t.wall_s.size(); ++i) before_last += t.wall_s[i];
  EXPECT_LT(before_last, budget.max_seconds);
  EXPECT_GE(before_last + t.wall_s.back(), budget.max_seconds);
}

TEST(FrameTiming, Spread) {
  Spread s = spread({3, 1, 2});
  EXPECT_EQ(s.median, 2);
  EXPECT_EQ(s.min, 1);
  EXPECT_EQ(s.max, 3);
  EXPECT_EQ(s.n, 3u);
  s = spread({4, 1, 3, 2});
  EXPECT_EQ(s.median, 2.5);
  s = spread({});
  EXPECT_EQ(s.n, 0u);
  EXPECT_EQ(s.median, 0);
}
