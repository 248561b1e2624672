#pragma once
// A CSV file as written by swarmagg (header line, comma separated, no quoting), read back so
// the report is computed from the files a user can open, whether the run was just made or
// reused.
#include <filesystem>
#include <string>
#include <vector>

namespace swarmagg {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  // Index of a header column; throws std::runtime_error naming the column when missing.
  std::size_t column(const std::string& name) const;
  // The cell as a number; empty cells are NaN (a column a model does not predict).
  double number(std::size_t row, std::size_t column) const;
};

CsvTable read_csv(const std::filesystem::path& file);

}  // namespace swarmagg
