#include "output/format_text.hpp"

#include <cstdio>

namespace swarmagg {

std::string format_text(const char* pattern, double a, double b, double c) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
  return buffer;
}

}  // namespace swarmagg
