#pragma once
// Cooperative interruption: SIGINT/SIGTERM set a flag that long loops poll; the run then
// stops, keeps what is complete and exits 130 (143 for SIGTERM).
#include <stdexcept>

namespace swarmagg {

class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal_number)
      : std::runtime_error("interrupted"), signal_number_(signal_number) {}
  int exit_code() const { return 128 + signal_number_; }

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

}  // namespace swarmagg
