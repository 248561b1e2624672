#include "analysis/replicate_spread.hpp"

#include <cmath>

#include "core/rng.hpp"

namespace swarmagg {
namespace {

constexpr std::uint64_t kSpreadSeed = 0x5EED5EED5EED5EEDull;

// How many times each of n replicates is drawn in resample b, less 1: a resample's mean minus
// the sample's is the sum of these weights times the values, over n.
std::vector<double> extra_draws(int resample, std::size_t n) {
  std::vector<double> weights(n, -1.0);
  for (std::size_t k = 0; k < n; ++k) weights[resampled_replicate(resample, k, n)] += 1.0;
  return weights;
}

// A resample's mean spreads about the sample's by sqrt((n - 1) / n) of the mean's own
// spread (the bootstrap's plug-in variance): scaled back, as the floors are unbiased.
double unbiased(double spread, std::size_t n) {
  return spread * std::sqrt(static_cast<double>(n) / static_cast<double>(n - 1));
}

}  // namespace

std::size_t resampled_replicate(int resample, std::size_t k, std::size_t n) {
  const std::uint64_t h =
      mix64(kSpreadSeed ^ mix64(static_cast<std::uint64_t>(resample) * 0x9E3779B97F4A7C15ull + k));
  return static_cast<std::size_t>(h % n);
}

double noa_spread(const NoaSeries& simulation) {
  if (simulation.values.empty() || simulation.values.front().size() < 2) return 0.0;
  const std::size_t n = simulation.values.front().size();
  double total = 0.0;
  for (int b = 0; b < kSpreadResamples; ++b) {
    const std::vector<double> weights = extra_draws(b, n);
    double squares = 0.0;
    for (const std::vector<double>& at_step : simulation.values) {
      double difference = 0.0;
      for (std::size_t k = 0; k < n && k < at_step.size(); ++k)
        difference += weights[k] * at_step[k];
      difference /= static_cast<double>(n);
      squares += difference * difference;
    }
    total += std::sqrt(squares / static_cast<double>(simulation.values.size()));
  }
  return unbiased(total / kSpreadResamples, n);
}

double partition_spread(const std::vector<Distribution>& replicates) {
  const std::size_t n = replicates.size();
  if (n < 2) return 0.0;
  Distribution sample;
  for (const Distribution& replicate : replicates) {
    for (const auto& [partition, fraction] : replicate)
      sample[partition] += fraction / static_cast<double>(n);
  }
  double total = 0.0;
  for (int b = 0; b < kSpreadResamples; ++b) {
    Distribution resample;
    for (std::size_t k = 0; k < n; ++k) {
      for (const auto& [partition, fraction] : replicates[resampled_replicate(b, k, n)])
        resample[partition] += fraction / static_cast<double>(n);
    }
    total += total_variation(sample, resample);
  }
  return unbiased(total / kSpreadResamples, n);
}

}  // namespace swarmagg
