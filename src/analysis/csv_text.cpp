#include "analysis/csv_text.hpp"

#include <charconv>
#include <cmath>

namespace swarmagg {

std::string csv_number(double value) {
  if (std::isnan(value)) return "";
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

}  // namespace swarmagg
