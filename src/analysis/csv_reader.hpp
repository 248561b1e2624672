#pragma once
// A CSV file as written by swarmagg (header line, comma separated, no quoting), read one row at
// a time: a long run's model.csv and timeseries.csv reach gigabytes, which read whole as text
// cells (analysis/csv_table.hpp) would take many times their size in memory. The same checks
// as a whole read: a damaged or cut short file is an InputError naming the file, the line and
// what was wrong.
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace swarmagg {

class CsvReader {
 public:
  // Reads the header; InputError when the file cannot be read (missing, a folder).
  explicit CsvReader(const std::filesystem::path& file);

  const std::vector<std::string>& header() const { return header_; }
  // Index of a header column; InputError naming the file and the column when missing.
  std::size_t column(const std::string& name) const;

  // Moves to the next row (blank lines are skipped); false at the end of the file. A row with
  // another number of fields than the header is an InputError naming its line.
  bool next();
  const std::vector<std::string>& cells() const { return cells_; }
  const std::string& cell(std::size_t column) const { return cells_.at(column); }
  // The cell as a number: empty is NaN (a column a model does not predict), a cell that is
  // not entirely a number an InputError naming the file, line and column.
  double number(std::size_t column) const;
  std::size_t line() const { return line_; }  // of the current row (1 is the header)

 private:
  std::ifstream in_;
  std::string source_;
  std::vector<std::string> header_;
  std::vector<std::string> cells_;
  std::string text_;
  std::size_t line_ = 1;

  void throw_if_unreadable() const;
  std::string unreadable() const;
};

// Shared with CsvTable, which reads every row at once.
std::size_t csv_column(const std::vector<std::string>& header, const std::string& name,
                       const std::string& source);
// The cell as a number (empty is NaN), or none when it is not entirely a number.
std::optional<double> parse_csv_number(std::string_view text);
// `where` names the file and line (or the row of a table made in memory).
[[noreturn]] void throw_not_a_number(const std::string& where, const std::string& column,
                                     std::string_view text);

}  // namespace swarmagg
