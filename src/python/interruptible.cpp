#include "python/interruptible.hpp"

#include <chrono>
#include <csignal>

namespace swarmagg::python::detail {

bool wait_or_interrupt(const std::future<void>& done, std::atomic<int>& stop) {
  using namespace std::chrono_literals;
  while (true) {
    {
      pybind11::gil_scoped_release no_gil;
      if (done.wait_for(50ms) == std::future_status::ready) return true;
    }
    if (PyErr_CheckSignals() != 0) break;
  }
  stop.store(SIGINT);
  {
    pybind11::gil_scoped_release no_gil;
    done.wait();
  }
  return false;
}

}  // namespace swarmagg::python::detail
