#pragma once
// "The two arms' escape fractions are equal", each arm's fraction its replicates' escapes over
// their LEAVE attempts, pooled. Replicates differ more than binomially (each has aggregates of
// its own: dispersion chi^2/df of 1.9 to 5.2 in the paper's and the docs' worlds), so a pooled
// z test counting every attempt as independent rejected 15-42 % of arms that were the same
// world at the 5 % level. The variance of each arm's fraction is therefore taken from its
// replicates that made attempts, as the ratio estimator's linearised (cluster-robust)
// variance m/(m-1) sum_r (k_r - p n_r)^2 / N^2, and the arms are compared as Welch compares
// means, with Welch-Satterthwaite degrees of freedom from m - 1 per arm: 2.5-5.4 % of such
// arms rejected over the same splits (2 to 20 replicates an arm). Where no replicate of either
// arm strays from its arm's fraction (a few attempts each), the replicates show no spread to
// go by, and the binomial variance of the pooled z test is used instead.
#include <cstdint>
#include <vector>

namespace swarmagg {

struct ReplicateTrials {
  std::int64_t successes = 0;
  std::int64_t trials = 0;
};

struct ProportionResult {
  bool judged = false;      // two replicates with attempts or more in each arm
  double fraction_a = 0.0;  // pooled: all successes over all trials
  double fraction_b = 0.0;
  double t = 0.0;        // (b - a) over the standard error
  double dof = 0.0;      // 0: the binomial fallback (normal), or nothing to judge
  double p_value = 1.0;  // two-sided
};

ProportionResult replicate_proportion_test(const std::vector<ReplicateTrials>& a,
                                           const std::vector<ReplicateTrials>& b);

}  // namespace swarmagg
