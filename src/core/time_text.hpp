#pragma once
// A simulated time (step * dt) as every CSV prints it. step * dt carries rounding noise
// (3 * 0.1 = 0.30000000000000004); twelve significant digits drop it and still tell apart
// the steps of 10^7 tu at dt = 0.1, where the stream default of six digits would not.
#include <cstdio>
#include <string>

namespace swarmagg {

inline std::string time_text(double time) {
  char buffer[32];
  const int length = std::snprintf(buffer, sizeof buffer, "%.12g", time);
  return std::string(buffer, static_cast<std::size_t>(length));
}

}  // namespace swarmagg
