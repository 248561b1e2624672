#include "run/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "run/interrupt.hpp"

namespace swarmagg {

void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& task,
                  const std::function<void()>& while_waiting) {
  if (count == 0) return;
  const auto workers = static_cast<std::size_t>(std::max(threads, 1));
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::condition_variable all_done;
  std::size_t running = 0;
  std::exception_ptr failure;
  auto fail = [&](std::exception_ptr error) {
    std::lock_guard lock(mutex);
    if (!failure) failure = std::move(error);
    next = count;  // hand out no more tasks
  };
  const std::atomic<int>* stop_request = InterruptScope::current();
  auto work = [&] {
    const InterruptScope scope(stop_request);
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        task(i);
      } catch (...) {
        fail(std::current_exception());
      }
    }
    std::lock_guard lock(mutex);
    --running;
    all_done.notify_all();
  };
  std::vector<std::thread> pool;
  try {
    for (std::size_t t = 0; t < std::min(workers, count); ++t) {
      {
        std::lock_guard lock(mutex);
        ++running;
      }
      try {
        pool.emplace_back(work);
      } catch (...) {
        std::lock_guard lock(mutex);
        --running;
        throw;
      }
    }
  } catch (...) {  // could not start a thread: let the started ones stop, then report
    fail(std::current_exception());
  }
  std::unique_lock lock(mutex);
  while (running > 0) {
    if (while_waiting) {
      lock.unlock();
      while_waiting();
      lock.lock();
    }
    all_done.wait_for(lock, std::chrono::milliseconds(250), [&] { return running == 0; });
  }
  lock.unlock();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace swarmagg
