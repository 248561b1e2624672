#pragma once
// Long calls (run, rates, sweep, a model) run without the GIL and stop soon after Ctrl-C.
// The work runs on a worker thread, in the library's own thread pool below it; the calling
// thread waits without the GIL and, every 50 ms, lets Python handle its signals. When a
// handler raises (Ctrl-C: KeyboardInterrupt), the call's own stop request (an InterruptScope
// of run/interrupt.hpp, open on its worker and pool) asks the work to stop at its next check,
// which the library's runs pass at least every 1024 steps; calls in other Python threads go
// on. Whatever the work writes, it writes atomically, so an interrupted call leaves nothing
// half-written. Python's own handlers stay in place.
#include <pybind11/pybind11.h>

#include <atomic>
#include <csignal>
#include <future>
#include <thread>
#include <utility>

#include "run/interrupt.hpp"

namespace swarmagg::python {

namespace detail {
// Waits for `done` without the GIL; false when a Python signal handler raised meanwhile
// (the work was then asked to stop through `stop` and has finished, and the Python error is
// set). In a daemon thread when the interpreter shuts down, taking the GIL back ends the
// thread (pthread_exit: an unwind that no frame may stop, and that a noexcept frame, such
// as a destructor's, turns into std::terminate): the GIL is taken back outside any destructor.
bool wait_or_interrupt(const std::future<void>& done, std::atomic<int>& stop);

// Asks the worker to stop and joins it on the way out, whatever way that is (the unwind of a
// thread that Python ends at shutdown included: a joinable std::thread destroyed terminates).
class StopAndJoin {
 public:
  StopAndJoin(std::thread& worker, std::atomic<int>& stop) : worker_(worker), stop_(stop) {}
  ~StopAndJoin() {
    if (!worker_.joinable()) return;
    stop_.store(SIGINT);
    worker_.join();
  }
  StopAndJoin(const StopAndJoin&) = delete;
  StopAndJoin& operator=(const StopAndJoin&) = delete;

 private:
  std::thread& worker_;
  std::atomic<int>& stop_;
};
}  // namespace detail

template <typename Work>
auto call_interruptibly(Work work) -> decltype(work()) {
  using Result = decltype(work());
  std::packaged_task<Result()> task(std::move(work));
  std::future<Result> result = task.get_future();
  std::promise<void> finished;
  std::future<void> done = finished.get_future();
  std::atomic<int> stop{0};
  std::thread worker([&task, &finished, &stop] {
    const InterruptScope scope(&stop);
    task();
    finished.set_value();
  });
  const detail::StopAndJoin joined_on_exit(worker, stop);
  const bool completed = detail::wait_or_interrupt(done, stop);
  worker.join();
  if (!completed) throw pybind11::error_already_set();
  return result.get();
}

}  // namespace swarmagg::python
