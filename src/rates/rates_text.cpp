#include "rates/rates_text.hpp"

#include <cstdio>

namespace swarmagg {

namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
  return buffer;
}

}  // namespace

std::vector<std::string> rate_summary_lines(const std::vector<RateRow>& rows) {
  std::vector<std::string> lines;
  for (const RateRow& row : rows) {
    const RateEstimate& e = row.estimate;
    std::string line = row.term + (row.size ? " " + std::to_string(*row.size) : "") + ": ";
    if (!e.rate) {
      line += "too few events (" + std::to_string(e.events) + ")";
    } else {
      line += format("%.4g [%.4g, %.4g]", *e.rate, *e.low, *e.high) + " from " +
              std::to_string(e.events) + " events";
      for (const ModelTerm& m : row.models) {
        if (m.rate <= 0.0) continue;
        line += "; /" + m.variant +
                format(" %.3f [%.3f, %.3f]", *e.rate / m.rate, *e.low / m.rate, *e.high / m.rate);
      }
    }
    lines.push_back(line);
  }
  return lines;
}

}  // namespace swarmagg
