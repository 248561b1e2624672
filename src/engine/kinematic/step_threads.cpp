#include "engine/kinematic/step_threads.hpp"

namespace swarmagg {

StepThreads::~StepThreads() {
  stop_workers();
}

void StepThreads::stop_workers() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  start_.notify_all();
  for (std::thread& t : workers_) t.join();
  workers_.clear();
  stopping_ = false;
}

void StepThreads::resize(int threads) {
  const int wanted = threads < 1 ? 0 : threads - 1;
  if (wanted == static_cast<int>(workers_.size())) return;
  stop_workers();
  for (int k = 0; k < wanted; ++k) workers_.emplace_back([this] { worker_loop(); });
}

void StepThreads::work() {
  for (int k = next_task_.fetch_add(1); k < tasks_; k = next_task_.fetch_add(1)) {
    call_(context_, k);
  }
}

void StepThreads::dispatch(int tasks, void* context, Trampoline call) {
  {
    std::lock_guard lock(mutex_);
    context_ = context;
    call_ = call;
    tasks_ = tasks;
    next_task_.store(0);
    busy_workers_ = static_cast<int>(workers_.size());
    ++generation_;
  }
  start_.notify_all();
  work();
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return busy_workers_ == 0; });
}

void StepThreads::worker_loop() {
  std::uint64_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      start_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
    }
    work();
    std::lock_guard lock(mutex_);
    if (--busy_workers_ == 0) done_.notify_one();
  }
}

}  // namespace swarmagg
