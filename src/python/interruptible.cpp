#include "python/interruptible.hpp"

#include <chrono>
#include <csignal>

#include "run/interrupt.hpp"

namespace swarmagg::python::detail {

bool wait_or_interrupt(const std::future<void>& done) {
  using namespace std::chrono_literals;
  while (true) {
    {
      pybind11::gil_scoped_release no_gil;
      if (done.wait_for(50ms) == std::future_status::ready) return true;
    }
    if (PyErr_CheckSignals() != 0) break;
  }
  set_interrupt_signal(SIGINT);
  {
    pybind11::gil_scoped_release no_gil;
    done.wait();
  }
  set_interrupt_signal(0);
  return false;
}

}  // namespace swarmagg::python::detail
