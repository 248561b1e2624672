#include "run/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace swarmagg {
namespace {

std::atomic<int> received{0};

extern "C" void on_signal(int signal_number) {
  received.store(signal_number);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() {
  return received.load(std::memory_order_relaxed);
}

void throw_if_interrupted() {
  if (const int s = interrupt_signal()) throw Interrupted(s);
}

void set_interrupt_signal(int signal_number) {
  received.store(signal_number);
}

}  // namespace swarmagg
