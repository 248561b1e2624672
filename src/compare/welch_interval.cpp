#include "compare/welch_interval.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <stdexcept>

#include "models/sample_statistics.hpp"

namespace swarmagg {
WelchResult welch_interval(const std::vector<double>& a, const std::vector<double>& b,
                           double confidence) {
  if (a.size() < 2 || b.size() < 2)
    throw std::invalid_argument("Welch needs two values per sample");
  WelchResult w;
  w.mean_a = sample_mean(a);
  w.mean_b = sample_mean(b);
  w.difference = w.mean_b - w.mean_a;
  const double va = std::pow(sample_sd(a), 2) / static_cast<double>(a.size());
  const double vb = std::pow(sample_sd(b), 2) / static_cast<double>(b.size());
  const double se = std::sqrt(va + vb);
  if (se == 0.0) {
    // Both samples constant: the difference is known exactly.
    w.low = w.high = w.difference;
    w.p_value = w.difference == 0.0 ? 1.0 : 0.0;
    return w;
  }
  w.dof =
      (va + vb) * (va + vb) /
      (va * va / static_cast<double>(a.size() - 1) + vb * vb / static_cast<double>(b.size() - 1));
  const double half = student_t_quantile(w.dof, confidence) * se;
  w.low = w.difference - half;
  w.high = w.difference + half;
  const boost::math::students_t t(w.dof);
  w.p_value = 2.0 * boost::math::cdf(boost::math::complement(t, std::abs(w.difference) / se));
  return w;
}

}  // namespace swarmagg
