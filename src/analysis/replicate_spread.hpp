#pragma once
// The simulation's own noise, by the metric its model errors use: how far the replicates'
// summary (the mean NOA curve, the mean partition time fractions) moves when the replicates
// are drawn again. The mean, over kSpreadResamples bootstrap resamples (as many replicates,
// drawn with replacement), of the error between a resample's summary and the sample's, times
// sqrt(n / (n - 1)) against the bootstrap's shrinking of the spread with few replicates.
// Where the replicates settle at different values (a Soysal run whose NOA no longer moves),
// it exceeds the noise floor, whose own process mixes, and is the fairer yardstick.
// Deterministic: the resamples come from a fixed hash sequence, not a clock.
#include <cstdint>
#include <vector>

#include "analysis/noa_error.hpp"
#include "analysis/partition_comparison.hpp"

namespace swarmagg {

inline constexpr int kSpreadResamples = 2000;

// NOA RMSE between a resample's mean curve and the sample's; 0 with one replicate.
double noa_spread(const NoaSeries& simulation);
// Total-variation distance between a resample's mean distribution and the sample's.
double partition_spread(const std::vector<Distribution>& replicates);

// Replicate k of a resample b of n replicates (a fixed hash, the same on every machine).
std::size_t resampled_replicate(int resample, std::size_t k, std::size_t n);

}  // namespace swarmagg
