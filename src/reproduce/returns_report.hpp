#pragma once
// REPORT.md's sections on returns and noise floors (docs/models-returns.md): every model
// error beside its noise floor, the Soysal runs' NOA and largest-aggregate distributions with
// their stationarity, the leave-timeout series, and "why the models miss", written from the
// measured return fractions and the errors' ratios to their floors.
#include <string>
#include <vector>

#include "reproduce/figure_result.hpp"
#include "reproduce/timeout_series.hpp"

namespace swarmagg {

// Pooled over the sizes from `smallest` on: returns / attempts and the mean return time (tu).
struct ReturnSummary {
  std::uint64_t attempts = 0, returns = 0;
  // Over the `timed` returns: rates.csv times a size's returns only from 10 of them on.
  double mean_time = 0.0;  // 0 without timed returns
  std::uint64_t timed = 0;
  double fraction() const {
    return attempts ? static_cast<double>(returns) / static_cast<double>(attempts) : 0.0;
  }
};
ReturnSummary pooled_returns(const std::vector<RateRow>& rates, int smallest = 3);

// The share of all joins that were returns (1 - new joins / joins), 0 without joins.
double returning_share_of_joins(const std::vector<RateRow>& rates);

std::string noise_floor_section(const std::vector<FigureResult>& results,
                                const std::vector<TimeoutPoint>& series);
std::string soysal_distribution_section(const std::vector<FigureResult>& results);
std::string timeout_series_section(const std::vector<TimeoutPoint>& series);
std::string why_models_miss_section(const std::vector<FigureResult>& results,
                                    const std::vector<TimeoutPoint>& series);

}  // namespace swarmagg
