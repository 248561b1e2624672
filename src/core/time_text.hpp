#pragma once
// A simulated time (step * dt) as every CSV prints it. step * dt carries rounding noise
// (3 * 0.1 = 0.30000000000000004); twelve significant digits drop it and still tell apart
// the steps of 10^6 tu at dt = 0.1 (up to 10^10 tu), where a stream's six digits would not.
#include <cstdio>
#include <string>

namespace swarmagg {

inline std::string time_text(double time) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12g", time);  // at most 19 characters: no overflow
  return buffer;
}

}  // namespace swarmagg
