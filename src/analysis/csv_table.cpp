#include "analysis/csv_table.hpp"

#include <cmath>

#include "analysis/csv_reader.hpp"

namespace swarmagg {

std::size_t CsvTable::column(const std::string& name) const {
  return csv_column(header, name, source);
}

double CsvTable::number(std::size_t row, std::size_t column) const {
  const auto& cells = rows.at(row);
  if (column >= cells.size()) return std::nan("");
  if (const std::optional<double> value = parse_csv_number(cells[column])) return *value;
  throw_not_a_number(source.empty() ? "CSV row " + std::to_string(row + 1)
                                    : source + ":" + std::to_string(line_of.at(row)),
                     column < header.size() ? header[column] : "?", cells[column]);
}

CsvTable read_csv(const std::filesystem::path& file) {
  CsvReader reader(file);
  CsvTable table{.header = reader.header(), .rows = {}, .source = file.string(), .line_of = {}};
  while (reader.next()) {
    table.rows.push_back(reader.cells());
    table.line_of.push_back(reader.line());
  }
  return table;
}

}  // namespace swarmagg
