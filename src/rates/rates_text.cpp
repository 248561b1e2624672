#include "rates/rates_text.hpp"

#include <cstdint>

#include "output/format_text.hpp"

namespace swarmagg {

std::vector<std::string> rate_summary_lines(const std::vector<RateRow>& rows) {
  std::vector<std::string> lines;
  for (const RateRow& row : rows) {
    const RateEstimate& e = row.estimate;
    std::string line = row.term + (row.size ? " " + std::to_string(*row.size) : "") + ": ";
    // A fraction (returns per LEAVE attempt) needs attempts, not events: "0 of 19" is a
    // measurement, where "from 0 events" read as one too few to report.
    const bool fraction = row.term == "return";
    const auto trials = static_cast<std::uint64_t>(e.exposure);
    const bool geometry = row.term == "radius" || row.term == "rim";
    if (!e.rate) {
      // A size's geometry is a regression over replicates: many observations in one
      // replicate still give no interval.
      line += fraction   ? "too few attempts (" + std::to_string(trials) + ")"
              : geometry ? "not estimated (" + std::to_string(e.events) +
                               " observations; needs 10, from 2 replicates or more)"
                         : "too few events (" + std::to_string(e.events) + ")";
    } else {
      line += format_text("%.4g [%.4g, %.4g]", *e.rate, *e.low, *e.high);
      line += fraction
                  ? ": " + std::to_string(e.events) + " of " + std::to_string(trials) +
                        " attempts returned"
                  : " from " + std::to_string(e.events) + (geometry ? " observations" : " events");
      for (const ModelTerm& m : row.models) {
        if (m.rate <= 0.0) continue;
        line +=
            "; /" + m.variant +
            format_text(" %.3f [%.3f, %.3f]", *e.rate / m.rate, *e.low / m.rate, *e.high / m.rate);
      }
    }
    lines.push_back(line);
  }
  return lines;
}

}  // namespace swarmagg
