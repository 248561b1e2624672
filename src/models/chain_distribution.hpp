#pragma once
// Distributions of a finite continuous-time Markov chain given its generator Q (rates per
// step), computed so that every arithmetic step adds or multiplies non-negative numbers:
// no cancellation, so results stay non-negative and accurate for any number of steps.
#include <Eigen/Dense>
#include <cstdint>
#include <optional>
#include <vector>

#include "models/output_grid.hpp"
#include "models/partition_chain.hpp"

namespace swarmagg {

// Row j is the distribution after steps[j] steps from distribution `initial`, initial expm(k Q).
// With the chain's stationary distribution, propagation stops once the distribution is
// within 1e-13 of it in total variation (every later one is at least as close).
// `check`, when given, is called with 0 now and then: the caller's check for Ctrl-C (a large
// chain takes seconds).
Eigen::MatrixXd transient_distributions(const Generator& generator, const Eigen::VectorXd& initial,
                                        const std::vector<std::int64_t>& steps,
                                        const std::optional<Eigen::VectorXd>& stationary = {},
                                        const WalkProgress& check = {});

// Row j is the distribution after steps[j] steps from state `initial`, e_initial expm(k Q).
// With the chain's stationary distribution, propagation stops once the distribution is
// within 1e-13 of it in total variation (every later one is at least as close).
Eigen::MatrixXd transient_distributions(const Generator& generator, int initial,
                                        const std::vector<std::int64_t>& steps,
                                        const std::optional<Eigen::VectorXd>& stationary = {},
                                        const WalkProgress& check = {});

// The stationary distribution (pi Q = 0, sum pi = 1) of an irreducible chain; `check` as for
// transient_distributions (5 s for the 5604 partitions of N = 30).
Eigen::VectorXd stationary_distribution(const Generator& generator, const WalkProgress& check = {});

}  // namespace swarmagg
