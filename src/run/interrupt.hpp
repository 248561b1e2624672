#pragma once
// Cooperative interruption: SIGINT/SIGTERM set a flag that long loops poll; the run then
// stops, keeps what is complete and exits 130 (143 for SIGTERM).
#include <atomic>
#include <stdexcept>

namespace swarmagg {

class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal_number)
      : std::runtime_error("interrupted"), signal_number_(signal_number) {}
  int exit_code() const { return 128 + signal_number_; }
  int signal_number() const { return signal_number_; }

 private:
  int signal_number_;
};

// Installs the SIGINT/SIGTERM handlers (idempotent).
void install_interrupt_handlers();
// The signal received so far, or 0.
int interrupt_signal();
// Throws Interrupted when a signal was received.
void throw_if_interrupted();
// For tests: pretend a signal arrived (0 clears).
void set_interrupt_signal(int signal_number);

// A stop request that concerns one call only (the Python module's: Ctrl-C stops the call it
// interrupted, not the runs other Python threads have in flight). While a scope is open on a
// thread, interrupt_signal() there also reports the scope's request; parallel_for opens the
// caller's scope on its workers, so a call's whole pool sees it.
class InterruptScope {
 public:
  explicit InterruptScope(const std::atomic<int>* request);
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
  // The request of the scope open on this thread, or nullptr.
  static const std::atomic<int>* current();

 private:
  const std::atomic<int>* outer_;
};

}  // namespace swarmagg
