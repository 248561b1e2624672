#include "run/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>

namespace swarmagg {
namespace {

std::atomic<int> received{0};
thread_local const std::atomic<int>* scoped_request = nullptr;

// The first signal asks the work to stop where it checks (between steps, runs, figures). A
// second one stops the process at once: a controller stuck in a loop never reaches a check.
// Outputs are renamed into place, so none is left half-written; only hidden temporaries stay,
// which the next command writing there removes. Only async-signal-safe calls here.
extern "C" void on_signal(int signal_number) {
  if (received.exchange(signal_number) == 0) return;
  constexpr char kMessage[] = "\nswarmagg: stopped at once (a second signal)\n";
  if (::write(STDERR_FILENO, kMessage, sizeof kMessage - 1) < 0) {
    // Nothing to do: the process stops either way.
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
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
  if (const int s = received.load(std::memory_order_relaxed)) return s;
  return scoped_request != nullptr ? scoped_request->load(std::memory_order_relaxed) : 0;
}

void throw_if_interrupted() {
  if (const int s = interrupt_signal()) throw Interrupted(s);
}

void set_interrupt_signal(int signal_number) {
  received.store(signal_number);
}

InterruptScope::InterruptScope(const std::atomic<int>* request) : outer_(scoped_request) {
  scoped_request = request;
}

InterruptScope::~InterruptScope() {
  scoped_request = outer_;
}

const std::atomic<int>* InterruptScope::current() {
  return scoped_request;
}

}  // namespace swarmagg
