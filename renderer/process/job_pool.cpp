// The job pool (process/job_pool.h).
#include "process/job_pool.h"

#include <algorithm>
#include <atomic>
#include <exception>
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
  std::vector<std::thread> pool;
  for (size_t w = 0; w < threads; ++w) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace xval
