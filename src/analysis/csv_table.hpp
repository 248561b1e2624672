#pragma once
// A CSV file as written by swarmagg (header line, comma separated, no quoting), read back whole
// so the report is computed from the files a user can open, whether the run was just made or
// reused. For files that grow with a run's length, read row by row (analysis/csv_reader.hpp). A
// file damaged by hand or cut short is an InputError naming the file, the line and what was wrong,
// never a number silently dropped.
#include <filesystem>
#include <string>
#include <vector>

namespace swarmagg {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::string source;                // the file, for messages ("" for a table made in memory)
  std::vector<std::size_t> line_of;  // each row's line in the file (1 is the header)

  // Index of a header column; throws InputError naming the file and the column when missing.
  std::size_t column(const std::string& name) const;
  // The cell as a number; empty cells are NaN (a column a model does not predict). Anything
  // else that is not a whole number text is an InputError naming the file, line and column.
  double number(std::size_t row, std::size_t column) const;
};

// Every row must have the header's number of fields (a row cut short is an InputError).
CsvTable read_csv(const std::filesystem::path& file);

}  // namespace swarmagg
