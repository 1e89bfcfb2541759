// process/job_pool.h: every job runs once, on at most `workers` threads,
// and an exception comes out after every job ran.
#include <gtest/gtest.h>
#include <algorithm>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
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
  EXPECT_EQ(threads.count(std::this_thread::get_id()), 1u);  // this thread is one of the workers
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

// The weighted pool: jobs of weight 1/4 run four at once in a capacity of
// one, a job of weight 1 never runs beside another, and every job runs once.
TEST(JobPool, WeightedJobsFillTheCapacityAndNeverExceedIt) {
  const size_t n = 24;
  std::vector<std::atomic<int>> runs(n);
  std::mutex m;
  double used = 0.0, most_used = 0.0;
  int running_heavy_with_others = 0, most_light = 0, light = 0;
  auto weight = [](size_t i) { return i % 6 == 5 ? 1.0 : 0.25; };
  runWeightedJobPool(n, 1.0, weight, [&](size_t i) {
    {
      std::lock_guard<std::mutex> g(m);
      used += weight(i);
      most_used = std::max(most_used, used);
      if (weight(i) < 1.0) most_light = std::max(most_light, ++light);
      if (weight(i) == 1.0 && used > 1.0) ++running_heavy_with_others;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    {
      std::lock_guard<std::mutex> g(m);
      used -= weight(i);
      if (weight(i) < 1.0) --light;
    }
    ++runs[i];
  });
  for (size_t i = 0; i < n; ++i) EXPECT_EQ(runs[i].load(), 1) << "job " << i;
  EXPECT_LE(most_used, 1.0 + 1e-9);
  EXPECT_EQ(most_light, 4);  // the light jobs did run side by side
  EXPECT_EQ(running_heavy_with_others, 0);
}

TEST(JobPool, WeightedJobHeavierThanTheCapacityRunsAlone) {
  std::atomic<int> c{0};
  runWeightedJobPool(3, 1.0, [](size_t) { return 5.0; }, [&](size_t) { ++c; });
  EXPECT_EQ(c.load(), 3);
  EXPECT_THROW(runWeightedJobPool(2, 1.0, [](size_t) { return 0.0; }, [](size_t) {}), std::invalid_argument);
}

// The queue that grows while it runs (validate's renders and the compares
// they queue): a task queued by a running task runs; an urgent one starts
// before the tasks queued earlier that have not started; the capacity
// holds; an exception comes out once every task ran.
TEST(WeightedTaskQueue, TasksQueuedWhileRunningRunUrgentFirst) {
  WeightedTaskQueue q(1.0);  // one task of weight 1 at a time: a strict order
  std::mutex m;
  std::vector<std::string> order;
  auto log = [&](const std::string& s) {
    std::lock_guard<std::mutex> g(m);
    order.push_back(s);
  };
  q.push(1.0, [&] {
    log("a");
    q.push(1.0, [&] { log("a-follow-up"); }, true);  // urgent: before b and c
  });
  q.push(1.0, [&] { log("b"); });
  q.push(1.0, [&] {
    log("c");
    q.push(1.0, [&] { log("c-follow-up"); }, false);  // not urgent: after everything queued
  });
  q.run(4);
  EXPECT_EQ(order, (std::vector<std::string>{"a", "a-follow-up", "b", "c", "c-follow-up"}));
}

TEST(WeightedTaskQueue, CapacityHoldsAndExceptionsComeOutAfterEveryTask) {
  WeightedTaskQueue q(1.0);
  std::mutex m;
  double used = 0.0, most = 0.0;
  std::atomic<int> ran{0};
  for (int i = 0; i < 12; ++i) {
    const double w = i % 3 == 0 ? 1.0 : 0.25;
    q.push(w, [&, w, i] {
      {
        std::lock_guard<std::mutex> g(m);
        used += w;
        most = std::max(most, used);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      {
        std::lock_guard<std::mutex> g(m);
        used -= w;
      }
      ++ran;
      if (i == 4) throw std::runtime_error("task 4 failed");
    });
  }
  EXPECT_THROW(q.run(8), std::runtime_error);
  EXPECT_EQ(ran.load(), 12);
  EXPECT_LE(most, 1.0 + 1e-9);
  EXPECT_GT(most, 0.25 + 1e-9);  // light tasks did run side by side
  EXPECT_THROW(q.push(0.0, [] {}), std::invalid_argument);
}
