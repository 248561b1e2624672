#include "output/timeseries_csv.hpp"

#include <cstdio>

namespace swarmagg {
namespace {

// step * dt carries rounding noise (0.7000000000000001); twelve digits drop it.
std::string format_time(double time) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12g", time);
  return buffer;
}

}  // namespace

std::string timeseries_csv_line(const TimeseriesRow& row) {
  std::string line;
  auto field = [&line](const std::string& text) {
    if (!line.empty()) line += ',';
    line += text;
  };
  field(std::to_string(row.replicate));
  field(std::to_string(row.step));
  field(format_time(row.time));
  field(std::to_string(row.noa));
  field(std::to_string(row.states.searching));
  field(std::to_string(row.states.waiting));
  field(std::to_string(row.states.leaving));
  field(std::to_string(row.states.approaching));
  field(std::to_string(row.largest));
  field(std::to_string(row.events.creations));
  field(std::to_string(row.events.growths));
  field(std::to_string(row.events.dissipations));
  field(std::to_string(row.events.shrinks));
  field(std::to_string(row.events.encounters));
  return line;
}

std::string timeseries_csv_lines(std::span<const TimeseriesRow> rows) {
  std::string text;
  for (const TimeseriesRow& row : rows) text += timeseries_csv_line(row) + "\n";
  return text;
}

std::string timeseries_csv(std::span<const TimeseriesRow> rows) {
  return std::string(kTimeseriesHeader) + "\n" + timeseries_csv_lines(rows);
}

}  // namespace swarmagg
