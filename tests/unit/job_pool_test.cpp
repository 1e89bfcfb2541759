// process/job_pool.h: every job runs once, on at most `workers` threads,
// and an exception comes out after every job ran.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "process/job_pool.h"

using namespace xval;

TEST(JobPool, RunsEveryJobOnceOnAtMostWorkersThreads) {
  const size_t n = 200;
  std::vector<std::atomic<int>> runs(n);
  std::mutex lock;
  std::set<std::thread::id> threads;
  std::atomic<int> running{0}, most{0};
  runJobPool(n, 3, [&](size_t i) {
    const int now = ++running;
    for (int m = most; now > m && !most.compare_exchange_weak(m, now);) {
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    ++runs[i];
    {
      std::lock_guard<std::mutex> g(lock);
      threads.insert(std::this_thread::get_id());
    }
    --running;
  });
  for (size_t i = 0; i < n; ++i) EXPECT_EQ(runs[i].load(), 1) << "job " << i;
  EXPECT_LE(threads.size(), 3u);
  EXPECT_LE(most.load(), 3);
  EXPECT_EQ(threads.count(std::this_thread::get_id()), 0u);  // this thread waits
}

TEST(JobPool, NoJobsAndNonPositiveWorkers) {
  int calls = 0;
  runJobPool(0, 4, [&](size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
  std::atomic<int> c{0};
  runJobPool(5, 0, [&](size_t) { ++c; });  // at least one thread
  EXPECT_EQ(c.load(), 5);
  EXPECT_GE(defaultWorkers(), 1);
}

TEST(JobPool, FirstExceptionIsRethrownAfterEveryJobRan) {
  std::atomic<int> ran{0};
  try {
    runJobPool(50, 4, [&](size_t i) {
      ++ran;
      if (i == 7) throw std::runtime_error("job 7 failed");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "job 7 failed");
  }
  EXPECT_EQ(ran.load(), 50);
}
