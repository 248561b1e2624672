#include "output/timeseries_csv.hpp"

#include "core/time_text.hpp"

namespace swarmagg {

std::string timeseries_csv_line(const TimeseriesRow& row) {
  std::string line;
  auto field = [&line](const std::string& text) {
    if (!line.empty()) line += ',';
    line += text;
  };
  field(std::to_string(row.replicate));
  field(std::to_string(row.step));
  field(time_text(row.time));
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
