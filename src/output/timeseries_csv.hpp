#pragma once
// timeseries.csv (docs/reference/outputs.md): one tidy row per replicate and recorded step,
// cumulative events.
#include <span>
#include <string>

#include "observers/timeseries_row.hpp"

namespace swarmagg {

inline constexpr const char* kTimeseriesHeader =
    "replicate,step,time,noa,searching,waiting,leaving,approaching,largest,creations,growths,"
    "dissipations,shrinks,encounters";

std::string timeseries_csv_line(const TimeseriesRow& row);
// The lines of `rows`, each ending in a newline: a long run's file is written a replicate's
// lines at a time (run/run_folder.cpp).
std::string timeseries_csv_lines(std::span<const TimeseriesRow> rows);
// The header and the lines: the whole file.
std::string timeseries_csv(std::span<const TimeseriesRow> rows);

}  // namespace swarmagg
