#include "models/chain_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swarmagg {

namespace {

// Uniformization: with Lambda >= every exit rate, U = I + Q/Lambda is a stochastic matrix
// and expm(h Q) = sum_n Poisson(n; Lambda h) U^n, a sum of non-negative terms. With
// Lambda h <= 1 the Poisson tail beyond 20 terms is below 1e-19, far below double precision.
constexpr double kLargestUniformizedMean = 1.0;
constexpr double kNegligibleTail = 1e-19;

// Once every row of E^(2^b) agrees within this, E^(2^b) is the rank-one limit 1 pi to that
// accuracy and every higher power equals it: the remaining squarings can be skipped.
constexpr double kConvergedSpread = 1e-15;

void normalise_rows(Eigen::MatrixXd& matrix) {
  matrix.array().colwise() /= matrix.rowwise().sum().array();
}

double largest_exit_rate(const Generator& generator) {
  return (-generator.diagonal()).maxCoeff();
}

bool rows_converged(const Eigen::MatrixXd& matrix) {
  const Eigen::RowVectorXd spread = matrix.colwise().maxCoeff() - matrix.colwise().minCoeff();
  return spread.maxCoeff() < kConvergedSpread;
}

// Multiplies the rows of `distributions` picked by `selected` by `transition`, in one product.
void advance_rows(Eigen::MatrixXd& distributions, const std::vector<Eigen::Index>& selected,
                  const Eigen::MatrixXd& transition) {
  if (selected.empty()) return;
  Eigen::MatrixXd rows(static_cast<Eigen::Index>(selected.size()), distributions.cols());
  for (std::size_t k = 0; k < selected.size(); ++k) rows.row(k) = distributions.row(selected[k]);
  rows = rows * transition;
  for (std::size_t k = 0; k < selected.size(); ++k) distributions.row(selected[k]) = rows.row(k);
}

}  // namespace

Eigen::MatrixXd one_step_transition(const Generator& generator) {
  const Eigen::Index n = generator.rows();
  const double exit_rate = n > 0 ? largest_exit_rate(generator) : 0.0;
  if (exit_rate <= 0.0) return Eigen::MatrixXd::Identity(n, n);
  // expm(Q) = expm(Q / 2^halvings)^(2^halvings), with Lambda / 2^halvings <= 1.
  const int halvings = std::max(0, static_cast<int>(std::ceil(std::log2(exit_rate / kLargestUniformizedMean))));
  const double mean = exit_rate / std::ldexp(1.0, halvings);
  Generator uniformized = generator / exit_rate;
  for (Eigen::Index i = 0; i < n; ++i) uniformized.coeffRef(i, i) += 1.0;

  Eigen::MatrixXd power = Eigen::MatrixXd::Identity(n, n);  // U^k
  double weight = std::exp(-mean);                           // Poisson(k; mean)
  double covered = weight;
  Eigen::MatrixXd transition = weight * power;
  for (int k = 1; 1.0 - covered > kNegligibleTail && weight > 0.0; ++k) {
    power = power * uniformized;
    weight *= mean / k;
    covered += weight;
    transition += weight * power;
  }
  normalise_rows(transition);
  for (int i = 0; i < halvings; ++i) {
    transition = transition * transition;
    normalise_rows(transition);
  }
  return transition;
}

// Binary powering shared by all requested steps: E^(2^b) is formed once by squaring, and
// each distribution whose step has bit b set is multiplied by it (powers of E commute).
// Cost: log2(max step) dense squarings, independent of how many steps are requested.
Eigen::MatrixXd transient_distributions(const Generator& generator, int initial,
                                        const std::vector<std::int64_t>& steps) {
  const Eigen::Index n = generator.rows();
  Eigen::MatrixXd distributions = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(steps.size()), n);
  distributions.col(initial).setOnes();
  std::vector<std::int64_t> remaining = steps;
  Eigen::MatrixXd power = one_step_transition(generator);  // E^(2^b)
  while (true) {
    std::vector<Eigen::Index> with_bit, still_running;
    for (std::size_t j = 0; j < remaining.size(); ++j) {
      if (remaining[j] & 1) with_bit.push_back(static_cast<Eigen::Index>(j));
      remaining[j] >>= 1;
      if (remaining[j] > 0) still_running.push_back(static_cast<Eigen::Index>(j));
    }
    advance_rows(distributions, with_bit, power);
    if (still_running.empty()) break;
    if (rows_converged(power)) {
      advance_rows(distributions, still_running, power);
      break;
    }
    power = power * power;
    normalise_rows(power);
  }
  return distributions;
}

// Grassmann-Taksar-Heyman state reduction: Gaussian elimination on pi Q = 0 in which every
// pivot is a sum of positive rates (never a difference), so each stationary probability is
// found to near machine relative accuracy even when it is 1e-30. Dense O(n^3): fine for
// the ~600 partitions of N = 20.
Eigen::VectorXd stationary_distribution(const Generator& generator) {
  using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  RowMajorMatrix rates = RowMajorMatrix(generator);
  rates.diagonal().setZero();
  const Eigen::Index n = rates.rows();
  for (Eigen::Index k = n - 1; k >= 1; --k) {
    const double exit_to_lower = rates.row(k).head(k).sum();
    if (!(exit_to_lower > 0.0)) throw std::logic_error("stationary distribution: chain is not irreducible");
    rates.col(k).head(k) /= exit_to_lower;
    for (Eigen::Index i = 0; i < k; ++i) {
      if (rates(i, k) != 0.0) rates.row(i).head(k) += rates(i, k) * rates.row(k).head(k);
    }
  }
  Eigen::VectorXd stationary = Eigen::VectorXd::Zero(n);
  if (n == 0) return stationary;
  stationary(0) = 1.0;
  for (Eigen::Index j = 1; j < n; ++j) stationary(j) = stationary.head(j).dot(rates.col(j).head(j));
  return stationary / stationary.sum();
}

}  // namespace swarmagg
