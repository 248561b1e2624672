#pragma once
// Welch's two-sample t interval for the difference of two means (unequal variances),
// with the Student t quantile from Boost.Math.
#include <vector>

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

// Mean and half-width of the t confidence interval of one sample's mean (0 for n < 2).
struct MeanInterval {
  double mean = 0.0;
  double half_width = 0.0;
};
MeanInterval mean_interval(const std::vector<double>& values, double confidence = 0.95);

}  // namespace swarmagg
