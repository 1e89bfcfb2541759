// A pool of worker threads over a list of independent jobs.
//
// runJobPool(count, workers, job) calls job(i) once for every i in
// [0, count), on min(workers, count) threads (at least one; this thread is
// one of them), each thread taking the next index from a shared counter, so the
// jobs start in index order and a long job does not hold up the others.
// It returns when every job has returned. An exception never leaves a
// worker thread (that would be std::terminate): the first one thrown is
// kept, the remaining jobs still run, and it is rethrown here once every
// thread has been joined. Jobs that must not stop at an error report it
// themselves (validate's and extremes' jobs record it as that job's error).
//
// defaultWorkers(): the hardware thread count, at least 1 (the default of
// every --jobs option).
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>

namespace xval {

int defaultWorkers();

void runJobPool(size_t count, int workers, const std::function<void(size_t index)>& job);

// runWeightedJobPool(count, capacity, weight, job): job(i) once for every
// i, taken in index order, as many at once as their weights fit in
// `capacity` (a job of weight w runs when the running jobs' weights plus w
// are at most capacity, or when nothing runs: a job heavier than the
// capacity runs alone). weight(i) > 0; e.g. capacity = cores and weight =
// the share of a core a job keeps busy. Exceptions as runJobPool.
void runWeightedJobPool(size_t count, double capacity, const std::function<double(size_t index)>& weight,
                        const std::function<void(size_t index)>& job);

// A weighted pool whose tasks may be queued while it runs (a task may
// queue others). Rules, as runWeightedJobPool's: the task at the head of
// the queue starts when the running tasks' weights plus its own are at
// most `capacity`, or when nothing runs (a weight above the capacity
// counts as the capacity); tasks start in queue order (the head waits, the
// others behind it too). The head: the oldest urgent task, else the oldest
// other one; so an urgent task starts before every task queued before it
// that has not started. run() returns once every task queued before it
// returns or while it runs has returned, on at most `threads` threads (at
// least one; this thread waits). Exceptions as runJobPool: the first is
// rethrown by run() once every task has run.
class WeightedTaskQueue {
 public:
  explicit WeightedTaskQueue(double capacity);
  // Throws std::invalid_argument for a weight not > 0. Thread-safe.
  void push(double weight, std::function<void()> task, bool urgent = false);
  void run(size_t threads);

 private:
  struct Task {
    double weight;
    std::function<void()> run;
  };
  double capacity_;
  std::mutex lock_;
  std::condition_variable changed_;
  std::deque<Task> urgent_, normal_;
  double used_ = 0.0;
  size_t running_ = 0;
};

}  // namespace xval
