#include "compare/proportion_test.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <stdexcept>

namespace swarmagg {
namespace {

struct ArmFraction {
  double fraction = 0.0;
  double variance = 0.0;  // of the pooled fraction
  double trials = 0.0;
};

ArmFraction arm_fraction(const std::vector<ReplicateTrials>& replicates) {
  double successes = 0.0, trials = 0.0;
  for (const ReplicateTrials& r : replicates) {
    successes += static_cast<double>(r.successes);
    trials += static_cast<double>(r.trials);
  }
  ArmFraction arm;
  arm.trials = trials;
  if (trials <= 0.0) return arm;
  arm.fraction = successes / trials;
  double squares = 0.0;
  for (const ReplicateTrials& r : replicates) {
    const double residual =
        static_cast<double>(r.successes) - arm.fraction * static_cast<double>(r.trials);
    squares += residual * residual;
  }
  const auto m = static_cast<double>(replicates.size());
  arm.variance = m / (m - 1.0) * squares / (trials * trials);
  return arm;
}

}  // namespace

ProportionResult replicate_proportion_test(const std::vector<ReplicateTrials>& a,
                                           const std::vector<ReplicateTrials>& b) {
  if (a.size() < 2 || b.size() < 2)
    throw std::invalid_argument("the escape-fraction test needs two replicates per arm");
  const ArmFraction fa = arm_fraction(a), fb = arm_fraction(b);
  ProportionResult r;
  r.fraction_a = fa.fraction;
  r.fraction_b = fb.fraction;
  if (fa.trials <= 0.0 || fb.trials <= 0.0) return r;
  const double difference = fb.fraction - fa.fraction;
  const double se = std::sqrt(fa.variance + fb.variance);
  if (se == 0.0) {
    // Every replicate of both arms at its arm's fraction: the difference is known exactly.
    r.p_value = difference == 0.0 ? 1.0 : 0.0;
    return r;
  }
  const double va = fa.variance, vb = fb.variance;
  r.dof =
      (va + vb) * (va + vb) /
      (va * va / static_cast<double>(a.size() - 1) + vb * vb / static_cast<double>(b.size() - 1));
  r.t = difference / se;
  const boost::math::students_t t(r.dof);
  r.p_value = 2.0 * boost::math::cdf(boost::math::complement(t, std::abs(r.t)));
  return r;
}

}  // namespace swarmagg
