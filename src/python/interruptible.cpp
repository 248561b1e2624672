#include "python/interruptible.hpp"

#include <chrono>
#include <csignal>

namespace swarmagg::python::detail {

bool wait_or_interrupt(const std::future<void>& done, std::atomic<int>& stop) {
  using namespace std::chrono_literals;
  while (true) {
    PyThreadState* thread = PyEval_SaveThread();
    const bool ready = done.wait_for(50ms) == std::future_status::ready;
    PyEval_RestoreThread(thread);  // not in a destructor: see the header
    if (ready) return true;
    if (PyErr_CheckSignals() != 0) break;
  }
  stop.store(SIGINT);
  PyThreadState* thread = PyEval_SaveThread();
  done.wait();
  PyEval_RestoreThread(thread);
  return false;
}

}  // namespace swarmagg::python::detail
