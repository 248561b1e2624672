#include "models/sample_statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace swarmagg {

double sample_mean(const std::vector<double>& values) {
  if (values.empty()) throw std::invalid_argument("sample_mean of no values");
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double sample_sd(const std::vector<double>& values) {
  if (values.size() < 2) return 0.0;
  const double mean = sample_mean(values);
  double squares = 0.0;
  for (const double value : values) squares += (value - mean) * (value - mean);
  return std::sqrt(squares / static_cast<double>(values.size() - 1));
}

double sample_quantile(std::vector<double> values, double q) {
  if (values.empty()) throw std::invalid_argument("sample_quantile of no values");
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (position - static_cast<double>(below)) * (values[above] - values[below]);
}

double student_t_quantile(double dof, double confidence) {
  const boost::math::students_t t(dof);
  return boost::math::quantile(t, 0.5 + confidence / 2.0);
}

MeanInterval mean_interval(const std::vector<double>& values, double confidence) {
  MeanInterval m;
  if (values.empty()) return m;
  m.mean = sample_mean(values);
  if (values.size() < 2) return m;
  const double n = static_cast<double>(values.size());
  m.half_width = student_t_quantile(n - 1.0, confidence) * sample_sd(values) / std::sqrt(n);
  return m;
}

}  // namespace swarmagg
