#include "rates/power_law_fit.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include "models/sample_statistics.hpp"

namespace swarmagg {

PowerLawFit fit_power_law(std::span<const PowerLawPoint> points, double confidence) {
  PowerLawFit fit;
  fit.sizes = static_cast<int>(points.size());
  std::set<double> sizes;
  for (const PowerLawPoint& p : points) {
    if (!(p.size > 0.0) || !(p.value > 0.0) || !(p.weight > 0.0)) {
      throw std::invalid_argument("fit_power_law: sizes, values and weights must be > 0");
    }
    sizes.insert(p.size);
  }
  if (static_cast<int>(sizes.size()) < kMinimumFitSizes) {
    fit.refused = std::to_string(sizes.size()) + " size(s) with enough observations; a fit needs " +
                  std::to_string(kMinimumFitSizes);
    return fit;
  }
  double total_weight = 0.0, x_mean = 0.0, y_mean = 0.0;
  for (const PowerLawPoint& p : points) {
    total_weight += p.weight;
    x_mean += p.weight * std::log(p.size);
    y_mean += p.weight * std::log(p.value);
  }
  x_mean /= total_weight;
  y_mean /= total_weight;
  double sxx = 0.0, sxy = 0.0;
  for (const PowerLawPoint& p : points) {
    const double dx = std::log(p.size) - x_mean;
    sxx += p.weight * dx * dx;
    sxy += p.weight * dx * (std::log(p.value) - y_mean);
  }
  const double b = sxy / sxx;
  const double log_a = y_mean - b * x_mean;
  double residual = 0.0;
  for (const PowerLawPoint& p : points) {
    const double e = std::log(p.value) - log_a - b * std::log(p.size);
    residual += p.weight * e * e;
  }
  const double n = static_cast<double>(points.size());
  const double sigma2 = residual / (n - 2.0);
  const double t = student_t_quantile(n - 2.0, confidence);
  const double b_half = t * std::sqrt(sigma2 / sxx);
  const double log_a_half = t * std::sqrt(sigma2 * (1.0 / total_weight + x_mean * x_mean / sxx));
  fit.b = FittedParameter{b, b - b_half, b + b_half};
  fit.a =
      FittedParameter{std::exp(log_a), std::exp(log_a - log_a_half), std::exp(log_a + log_a_half)};
  return fit;
}

}  // namespace swarmagg
