#pragma once
// A plot is some hundreds of pixels wide, and gnuplot takes minutes and a gigabyte to draw a
// curve of 10^6 points with its confidence band (the demo world over 10^6 tu, recorded every
// 10 steps). A time curve longer than kMostDrawnPoints is drawn from every k-th of its points
// and its last, k the smallest stride that keeps it within the limit; the plot's CSV holds
// the points drawn, and timeseries.csv and model.csv keep every recorded step. Shorter
// curves (every shipped world's) are drawn whole.
#include <cstddef>
#include <vector>

#include "analysis/model_table.hpp"
#include "analysis/step_series.hpp"

namespace swarmagg {

inline constexpr std::size_t kMostDrawnPoints = 10'000;

// The indices drawn of `count` points: all up to kMostDrawnPoints, else every k-th and the
// last.
std::vector<std::size_t> drawn_indices(std::size_t count);

StepSeries drawn_part(const StepSeries& series);
std::vector<ModelCurve> drawn_part(const std::vector<ModelCurve>& curves);

}  // namespace swarmagg
