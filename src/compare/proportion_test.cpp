#include "compare/proportion_test.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>

namespace swarmagg {
namespace {

struct ArmFraction {
  double fraction = 0.0;
  double variance = 0.0;  // of the pooled fraction, from the replicates' spread
  double successes = 0.0;
  double trials = 0.0;
  double replicates = 0.0;  // those that made attempts: one without says nothing of the fraction
};

ArmFraction arm_fraction(const std::vector<ReplicateTrials>& replicates) {
  ArmFraction arm;
  for (const ReplicateTrials& r : replicates) {
    if (r.trials <= 0) continue;
    arm.successes += static_cast<double>(r.successes);
    arm.trials += static_cast<double>(r.trials);
    arm.replicates += 1.0;
  }
  if (arm.replicates < 2.0) return arm;
  arm.fraction = arm.successes / arm.trials;
  double squares = 0.0;
  for (const ReplicateTrials& r : replicates) {
    const double residual =
        static_cast<double>(r.successes) - arm.fraction * static_cast<double>(r.trials);
    squares += residual * residual;  // 0 for a replicate without attempts
  }
  const double m = arm.replicates;
  arm.variance = m / (m - 1.0) * squares / (arm.trials * arm.trials);
  return arm;
}

// The pooled z test's normal p-value, for arms whose replicates show no spread.
double binomial_p_value(const ArmFraction& a, const ArmFraction& b, double& z) {
  const double pooled = (a.successes + b.successes) / (a.trials + b.trials);
  const double variance = pooled * (1.0 - pooled) * (1.0 / a.trials + 1.0 / b.trials);
  if (!(variance > 0.0)) return 1.0;  // every attempt of both arms alike
  z = (b.fraction - a.fraction) / std::sqrt(variance);
  return std::erfc(std::fabs(z) / std::sqrt(2.0));
}

}  // namespace

ProportionResult replicate_proportion_test(const std::vector<ReplicateTrials>& a,
                                           const std::vector<ReplicateTrials>& b) {
  const ArmFraction fa = arm_fraction(a), fb = arm_fraction(b);
  ProportionResult r;
  if (fa.replicates < 2.0 || fb.replicates < 2.0) return r;
  r.judged = true;
  r.fraction_a = fa.fraction;
  r.fraction_b = fb.fraction;
  const double va = fa.variance, vb = fb.variance;
  if (va + vb == 0.0) {
    r.p_value = binomial_p_value(fa, fb, r.t);
    return r;
  }
  const double se = std::sqrt(va + vb);
  r.dof =
      (va + vb) * (va + vb) / (va * va / (fa.replicates - 1.0) + vb * vb / (fb.replicates - 1.0));
  r.t = (fb.fraction - fa.fraction) / se;
  const boost::math::students_t t(r.dof);
  r.p_value = 2.0 * boost::math::cdf(boost::math::complement(t, std::abs(r.t)));
  return r;
}

}  // namespace swarmagg
