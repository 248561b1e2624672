#pragma once
// Summary statistics of a sample: the replicates of a run or of a stochastic model at one step.
#include <vector>

namespace swarmagg {

double sample_mean(const std::vector<double>& values);
double sample_sd(const std::vector<double>& values);  // n - 1 denominator; 0 for n < 2
// Linear interpolation between order statistics (R's type 7, numpy's default), q in [0, 1].
double sample_quantile(std::vector<double> values, double q);

// The two-sided Student t quantile: the t with P(|T| <= t) = confidence at `dof` degrees.
double student_t_quantile(double dof, double confidence);

// Mean and half-width of the t confidence interval of one sample's mean (0 for n < 2).
struct MeanInterval {
  double mean = 0.0;
  double half_width = 0.0;
};
MeanInterval mean_interval(const std::vector<double>& values, double confidence = 0.95);

}  // namespace swarmagg
