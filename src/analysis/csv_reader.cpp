#include "analysis/csv_reader.hpp"

#include <charconv>
#include <cmath>

#include "core/errors.hpp"

namespace swarmagg {
namespace {

// Splits `line` into `cells`, reusing their storage from row to row.
void split_line(const std::string& line, std::vector<std::string>& cells) {
  std::size_t count = 0;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string::npos ? line.size() : comma;
    if (count == cells.size()) cells.emplace_back();
    cells[count++].assign(line, start, end - start);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  cells.resize(count);
}

}  // namespace

std::size_t csv_column(const std::vector<std::string>& header, const std::string& name,
                       const std::string& source) {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return i;
  }
  throw InputError((source.empty() ? std::string("CSV") : source) + ": has no column '" + name +
                   "'");
}

std::optional<double> parse_csv_number(std::string_view text) {
  if (text.empty()) return std::nan("");
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

void throw_not_a_number(const std::string& where, const std::string& column,
                        std::string_view text) {
  throw InputError(where + ": column '" + column + "': expected a number, got '" +
                   std::string(text) + "'");
}

CsvReader::CsvReader(const std::filesystem::path& file) : in_(file), source_(file.string()) {
  if (!in_) throw InputError(unreadable());
  if (std::getline(in_, text_) && !text_.empty()) split_line(text_, header_);
  throw_if_unreadable();
}

// Why the file cannot be read, in the words a user can act on.
std::string CsvReader::unreadable() const {
  std::error_code error;
  if (std::filesystem::is_directory(source_, error))
    return source_ + ": is a folder; expected a CSV file";
  if (!std::filesystem::exists(source_, error)) return source_ + ": no such file";
  return "cannot read " + source_;
}

// A folder opens as a file and fails only when read (EISDIR), as does a failing disk: not the
// end of the file.
void CsvReader::throw_if_unreadable() const {
  if (in_.bad()) throw InputError(unreadable());
}

std::size_t CsvReader::column(const std::string& name) const {
  return csv_column(header_, name, source_);
}

bool CsvReader::next() {
  while (std::getline(in_, text_)) {
    ++line_;
    if (text_.empty()) continue;
    split_line(text_, cells_);
    if (cells_.size() != header_.size()) {
      throw InputError(source_ + ":" + std::to_string(line_) + ": expected " +
                       std::to_string(header_.size()) + " fields as the header has, got " +
                       std::to_string(cells_.size()) + " (a damaged or cut short file?)");
    }
    return true;
  }
  throw_if_unreadable();
  return false;
}

double CsvReader::number(std::size_t column) const {
  const std::string& text = cell(column);
  if (const std::optional<double> value = parse_csv_number(text)) return *value;
  throw_not_a_number(source_ + ":" + std::to_string(line_), header_[column], text);
}

}  // namespace swarmagg
