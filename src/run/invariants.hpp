#pragma once
// Invariants a replicate must keep after every step. Checked in Debug builds and under
// `--check`; a violation stops the run with an InvariantViolation naming the step, the
// agent and the values.
#include <stdexcept>

namespace swarmagg {

class Replicate;

class InvariantViolation : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void check_invariants(const Replicate& replicate);

}  // namespace swarmagg
