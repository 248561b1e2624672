#include "analysis/csv_table.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

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
  throw std::runtime_error("CSV has no column '" + name + "'");
}

double CsvTable::number(std::size_t row, std::size_t column) const {
  const auto& cells = rows.at(row);
  if (column >= cells.size() || cells[column].empty()) return std::nan("");
  return std::stod(cells[column]);
}

CsvTable read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  CsvTable table;
  std::string line;
  if (std::getline(in, line)) table.header = split_line(line);
  while (std::getline(in, line)) {
    if (!line.empty()) table.rows.push_back(split_line(line));
  }
  return table;
}

}  // namespace swarmagg
