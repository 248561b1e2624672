#pragma once
// A plot is some hundreds of pixels wide, and gnuplot takes minutes and a gigabyte to draw a
// curve of 10^6 points with its confidence band (the demo world over 10^6 tu, recorded every
// 10 steps). A time curve of more recorded steps than kMostDrawnPoints is drawn from every
// k-th of them and the last, k the smallest stride that keeps it within the limit, and only
// those steps are read from the run's files: the plot's memory does not grow with the run.
// The plot's CSV holds the points drawn; timeseries.csv and model.csv keep every recorded
// step. Shorter curves (every shipped world's) are drawn whole.
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/run_files.hpp"
#include "analysis/step_series.hpp"

namespace swarmagg {

inline constexpr std::size_t kMostDrawnPoints = 10'000;

// The indices drawn of `count` points: all up to kMostDrawnPoints, else every k-th and the
// last.
std::vector<std::size_t> drawn_indices(std::size_t count);

// The recorded steps of `world` (models/output_grid.hpp's record_grid) a time plot draws, as
// a filter for the readers; none (every step) when all are drawn.
StepFilter drawn_steps(const WorldSpec& world);

// `columns` of the run's timeseries.csv at the steps drawn. InputError naming the file when
// it holds none of them (a file cut short before its first row).
std::vector<StepSeries> read_drawn_series(const RunFiles& run,
                                          const std::vector<std::string>& columns);

}  // namespace swarmagg
