#include "config/leave_law.hpp"

#include <algorithm>

namespace swarmagg {

double leave_probability(LeaveLaw law, double p0, int size) {
  const double i = std::max(size, 1);
  switch (law) {
    case LeaveLaw::Constant:
      return p0;
    case LeaveLaw::Inverse:
      return p0 / i;
    case LeaveLaw::InverseSquare:
      return p0 / (i * i);
  }
  return p0;
}

}  // namespace swarmagg
