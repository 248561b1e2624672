#pragma once
// Welch's two-sample t interval for the difference of two means (unequal variances),
// with the Student t quantile from Boost.Math.
#include <vector>

#include "models/sample_statistics.hpp"  // mean_interval, for the one-sample case

namespace swarmagg {

struct WelchResult {
  double mean_a = 0.0;
  double mean_b = 0.0;
  double difference = 0.0;  // mean_b - mean_a
  double low = 0.0;         // confidence interval of the difference
  double high = 0.0;
  double dof = 0.0;      // Welch-Satterthwaite degrees of freedom (0 when undefined)
  double p_value = 1.0;  // two-sided, for "the means are equal"
};

WelchResult welch_interval(const std::vector<double>& a, const std::vector<double>& b,
                           double confidence = 0.95);

}  // namespace swarmagg
