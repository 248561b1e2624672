#pragma once
// A small pool of worker threads that one replicate's step borrows for its data-parallel
// passes. `run(tasks, task)` calls task(0) .. task(tasks - 1) on the pool and the calling
// thread, and returns when all are done. Callers make results independent of the thread
// count: each task writes only its own slice or its own buffer, and buffers are joined in
// task order. Nothing is allocated per call (the task is passed by reference, not wrapped).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace swarmagg {

class StepThreads {
 public:
  // Agents per task below which waking another thread costs more than it saves.
  static constexpr std::size_t kAgentsPerTask = 16384;

  StepThreads() = default;
  ~StepThreads();
  StepThreads(const StepThreads&) = delete;
  StepThreads& operator=(const StepThreads&) = delete;

  // Threads a step may use, the calling one included (1: everything runs inline).
  void resize(int threads);
  int size() const { return static_cast<int>(workers_.size()) + 1; }

  template <typename Task>
  void run(int tasks, Task& task) {
    if (tasks <= 1 || workers_.empty()) {
      for (int k = 0; k < tasks; ++k) task(k);
      return;
    }
    dispatch(tasks, &task, [](void* context, int k) { (*static_cast<Task*>(context))(k); });
  }

  // [first, last) of `count` items for task `task` of `tasks` (contiguous, in order).
  static std::size_t slice_begin(std::size_t count, int task, int tasks) {
    return count * static_cast<std::size_t>(task) / static_cast<std::size_t>(tasks);
  }

 private:
  using Trampoline = void (*)(void*, int);
  void dispatch(int tasks, void* context, Trampoline call);
  void work();
  void worker_loop();
  void stop_workers();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  std::uint64_t generation_ = 0;  // guarded by mutex_
  int busy_workers_ = 0;          // guarded by mutex_
  bool stopping_ = false;         // guarded by mutex_
  void* context_ = nullptr;
  Trampoline call_ = nullptr;
  int tasks_ = 0;
  std::atomic<int> next_task_{0};
};

}  // namespace swarmagg
