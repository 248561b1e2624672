#pragma once
// Summary statistics of the replicates of a stochastic model at one step.
#include <vector>

namespace swarmagg {

double sample_mean(const std::vector<double>& values);
double sample_sd(const std::vector<double>& values);  // n - 1 denominator; 0 for n < 2
// Linear interpolation between order statistics (R's type 7, numpy's default), q in [0, 1].
double sample_quantile(std::vector<double> values, double q);

}  // namespace swarmagg
