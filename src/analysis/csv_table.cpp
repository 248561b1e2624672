#include "analysis/csv_table.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace swarmagg {
namespace {

std::vector<std::string> split_line(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  std::string cell;
  while (std::getline(stream, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

}  // namespace

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return i;
  }
  throw InputError((source.empty() ? std::string("CSV") : source) + ": has no column '" + name +
                   "'");
}

double CsvTable::number(std::size_t row, std::size_t column) const {
  const auto& cells = rows.at(row);
  if (column >= cells.size() || cells[column].empty()) return std::nan("");
  const std::string& text = cells[column];
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    const std::string where = source.empty() ? "CSV row " + std::to_string(row + 1)
                                             : source + ":" + std::to_string(line_of.at(row));
    throw InputError(where + ": column '" + (column < header.size() ? header[column] : "?") +
                     "': expected a number, got '" + text + "'");
  }
  return value;
}

CsvTable read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError("cannot read " + file.string());
  CsvTable table;
  table.source = file.string();
  std::string line;
  std::size_t line_number = 1;
  if (std::getline(in, line)) table.header = split_line(line);
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty()) continue;
    std::vector<std::string> cells = split_line(line);
    if (cells.size() != table.header.size()) {
      throw InputError(table.source + ":" + std::to_string(line_number) + ": expected " +
                       std::to_string(table.header.size()) + " fields as the header has, got " +
                       std::to_string(cells.size()) + " (a damaged or cut short file?)");
    }
    table.rows.push_back(std::move(cells));
    table.line_of.push_back(line_number);
  }
  return table;
}

}  // namespace swarmagg
