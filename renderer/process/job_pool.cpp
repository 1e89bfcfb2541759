// The job pool (process/job_pool.h).
#include "process/job_pool.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <limits>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <mutex>
#include <thread>
#include <vector>

namespace xval {

int defaultWorkers() { return int(std::max(1u, std::thread::hardware_concurrency())); }

void runJobPool(size_t count, int workers, const std::function<void(size_t)>& job) {
  std::atomic<size_t> next{0};
  std::mutex lock;
  std::exception_ptr first_error;
  auto worker = [&]() {
    for (size_t i = next++; i < count; i = next++) {
      try {
        job(i);
      } catch (...) {
        std::lock_guard<std::mutex> g(lock);
        if (!first_error) first_error = std::current_exception();
      }
    }
  };
  const size_t threads = std::clamp<size_t>(size_t(std::max(1, workers)), 1, std::max<size_t>(1, count));
  // This thread is one of them: a frame's short passes (a few ms on two
  // cores) would otherwise pay for starting a thread it then waits on.
  std::vector<std::thread> pool;
  for (size_t w = 1; w < threads; ++w) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

void runWeightedJobPool(size_t count, double capacity, const std::function<double(size_t)>& weight,
                        const std::function<void(size_t)>& job) {
  if (count == 0) return;
  std::vector<double> w(count);
  double lightest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < count; ++i) {
    w[i] = std::min(weight(i), capacity);
    if (!(w[i] > 0.0)) throw std::invalid_argument("runWeightedJobPool: job " + std::to_string(i) +
                                                   " has weight " + std::to_string(w[i]) + ", not > 0");
    lightest = std::min(lightest, w[i]);
  }
  // Enough threads for the most jobs that can run at once.
  const size_t most = size_t(std::max(1.0, std::floor(capacity / lightest + 1e-9)));
  std::mutex lock;
  std::condition_variable freed;
  double used = 0.0;
  size_t running = 0, next = 0;
  std::exception_ptr first_error;
  auto worker = [&]() {
    std::unique_lock<std::mutex> g(lock);
    while (next < count) {
      const size_t i = next++;
      freed.wait(g, [&] { return running == 0 || used + w[i] <= capacity + 1e-9; });
      used += w[i];
      ++running;
      g.unlock();
      try {
        job(i);
      } catch (...) {
        std::lock_guard<std::mutex> e(lock);
        if (!first_error) first_error = std::current_exception();
      }
      g.lock();
      used -= w[i];
      --running;
      freed.notify_all();
    }
  };
  std::vector<std::thread> pool;
  for (size_t t = 0; t < std::min(most, count); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

WeightedTaskQueue::WeightedTaskQueue(double capacity) : capacity_(capacity) {
  if (!(capacity > 0.0)) throw std::invalid_argument("WeightedTaskQueue: capacity " + std::to_string(capacity) + ", not > 0");
}

void WeightedTaskQueue::push(double weight, std::function<void()> task, bool urgent) {
  if (!(weight > 0.0)) throw std::invalid_argument("WeightedTaskQueue: a task of weight " + std::to_string(weight) + ", not > 0");
  {
    std::lock_guard<std::mutex> g(lock_);
    (urgent ? urgent_ : normal_).push_back({std::min(weight, capacity_), std::move(task)});
  }
  changed_.notify_all();
}

void WeightedTaskQueue::run(size_t threads) {
  std::exception_ptr first_error;
  auto worker = [&]() {
    std::unique_lock<std::mutex> g(lock_);
    while (true) {
      // Wait for a head that fits, or for the end: nothing queued, nothing
      // running (a running task may still queue more).
      changed_.wait(g, [&] {
        const std::deque<Task>& q = !urgent_.empty() ? urgent_ : normal_;
        if (q.empty()) return running_ == 0;
        return running_ == 0 || used_ + q.front().weight <= capacity_ + 1e-9;
      });
      std::deque<Task>& q = !urgent_.empty() ? urgent_ : normal_;
      if (q.empty()) break;
      Task task = std::move(q.front());
      q.pop_front();
      used_ += task.weight;
      ++running_;
      g.unlock();
      try {
        task.run();
      } catch (...) {
        std::lock_guard<std::mutex> e(lock_);
        if (!first_error) first_error = std::current_exception();
      }
      g.lock();
      used_ -= task.weight;
      --running_;
      changed_.notify_all();
    }
    changed_.notify_all();  // the others see the end too
  };
  std::vector<std::thread> pool;
  for (size_t t = 0; t < std::max<size_t>(1, threads); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace xval
