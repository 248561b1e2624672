#include "rates/rates_csv.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "analysis/csv_table.hpp"
#include "analysis/csv_text.hpp"
#include "config/did_you_mean.hpp"
#include "core/errors.hpp"
#include "rates/poisson_interval.hpp"
#include "rates/rate_rows.hpp"

namespace swarmagg {

namespace {

// A term this version does not write (a misspelling, a hand-made row) would be read and then
// ignored by every model, which would say it kept its own value for lack of a measurement.
void check_term(const std::string& term, const std::string& where) {
  const std::vector<std::string> known(std::begin(kRateTerms), std::end(kRateTerms));
  if (std::find(known.begin(), known.end(), term) != known.end()) return;
  std::string list;
  for (const std::string& name : known) list += (list.empty() ? "" : ", ") + name;
  const std::optional<std::string> closest = closest_name(term, known);
  throw InputError(where + ": unknown term '" + term + "'" +
                   (closest ? "; did you mean '" + *closest + "'?" : "") + " (expected one of " +
                   list + ")");
}

// A rate (or return fraction) is its events over its exposure, given from kMinimumEvents
// events (trials, for a fraction) on: the models take the rate column, so one that disagrees
// with its counts (a hand edit) would be used while the counts said otherwise. A relative
// tolerance lets files rewritten with fewer digits through.
void check_rate_is_its_counts(const RateRow& row, const std::string& where,
                              const std::string& text) {
  static const std::vector<std::string> kCounted = {
      "creation", "pairup", "growth", "join", "join_new", "initial", "attempt", "escape", "return"};
  if (!row.estimate.rate || std::find(kCounted.begin(), kCounted.end(), row.term) == kCounted.end())
    return;
  const bool fraction = row.term == "return";
  const double counted =
      fraction ? row.estimate.exposure : static_cast<double>(row.estimate.events);
  if (counted < static_cast<double>(kMinimumEvents)) {
    const std::string unit = fraction ? " LEAVE attempts" : " events";
    throw InputError(where + ": a " + row.term + " rate from " + csv_number(counted) + unit +
                     " (got '" + text + "'): a measurement needs " +
                     std::to_string(kMinimumEvents) + unit + " or more; leave the cell empty");
  }
  const double expected = static_cast<double>(row.estimate.events) / row.estimate.exposure;
  if (std::abs(*row.estimate.rate - expected) > 1e-9 * expected) {
    throw InputError(where + ": got '" + text +
                     "', expected events / exposure = " + csv_number(expected));
  }
}

// Bounds that keep the casts to int and uint64 defined (and far above any real run).
constexpr double kMaxSize = 1e9;
constexpr double kMaxEvents = 1e15;

constexpr const char* kHeader =
    "term,size,events,exposure,rate,ci_low,ci_high,model,variant,model_rate";

std::string optional_number(const std::optional<double>& value) {
  return value ? csv_number(*value) : "";
}

std::string measured_columns(const RateRow& row) {
  const RateEstimate& e = row.estimate;
  return row.term + "," + (row.size ? std::to_string(*row.size) : "") + "," +
         std::to_string(e.events) + "," + csv_number(e.exposure) + "," + optional_number(e.rate) +
         "," + optional_number(e.low) + "," + optional_number(e.high);
}

// Repeated lines of a term (one per model variant) carry the same measurement.
bool same_measurement(const RateEstimate& a, const RateEstimate& b) {
  return a.events == b.events && a.exposure == b.exposure && a.rate == b.rate && a.low == b.low &&
         a.high == b.high;
}

}  // namespace

std::string rates_csv(const std::vector<RateRow>& rows) {
  std::string out = std::string(kHeader) + "\n";
  for (const RateRow& row : rows) {
    const std::string measured = measured_columns(row);
    if (row.models.empty()) out += measured + ",,,\n";
    for (const ModelTerm& m : row.models) {
      out += measured + "," + m.model + "," + m.variant + "," + csv_number(m.rate) + "\n";
    }
  }
  return out;
}

std::vector<RateRow> read_rates_csv(const std::filesystem::path& file) {
  if (std::error_code error; std::filesystem::is_directory(file, error)) {
    throw InputError(file.string() + ": is a folder; expected the rates.csv of `swarmagg rates` " +
                     "or `run --rates` (" + (file / "rates.csv").string() + "?)");
  }
  CsvTable table;
  try {
    table = read_csv(file);
  } catch (const std::exception& e) {
    throw InputError(file.string() + ": cannot read rates: " + e.what());
  }
  std::string header;
  for (const std::string& column : table.header) header += (header.empty() ? "" : ",") + column;
  if (header != kHeader) {
    throw InputError(file.string() + ":1: expected the rates.csv header `" + std::string(kHeader) +
                     "`");
  }
  std::vector<RateRow> rows;
  std::map<std::pair<std::string, int>, std::size_t> first_line;  // by term and size
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const std::vector<std::string>& cells = table.rows[i];
    // As CsvTable names a cell: file:line: column 'name'.
    const auto cell = [&](std::size_t column) {
      return file.string() + ":" + std::to_string(table.line_of.at(i)) + ": column '" +
             table.header[column] + "'";
    };
    // Every quantity of the file is a count, a duration or a rate: a hand-edited negative or
    // infinite value would otherwise flow into the model as -inf or nan in model.csv.
    auto number = [&](std::size_t column, bool may_be_empty) {
      const double value = table.number(i, column);  // names file, line and column
      const bool empty = std::isnan(value) && cells.at(column).empty();
      if ((empty && !may_be_empty) || (!empty && !(std::isfinite(value) && value >= 0.0))) {
        throw InputError(cell(column) + ": expected a finite number >= 0, got '" +
                         cells.at(column) + "'");
      }
      return value;
    };
    auto whole_number = [&](std::size_t column, double low, double high) {
      const double value = table.number(i, column);
      if (!(value == std::floor(value) && value >= low && value <= high)) {
        throw InputError(cell(column) + ": expected a whole number from " + csv_number(low) +
                         " to " + csv_number(high) + ", got '" + cells.at(column) + "'");
      }
      return value;
    };
    RateRow row{.term = cells.at(0)};
    check_term(row.term, cell(0));
    if (!cells.at(1).empty()) row.size = static_cast<int>(whole_number(1, 1, kMaxSize));
    row.estimate.events = static_cast<std::uint64_t>(whole_number(2, 0, kMaxEvents));
    row.estimate.exposure = number(3, false);
    // A return fraction counts returns among attempts: above 1 the model would lose a
    // negative number of agents per attempt.
    const bool fraction = row.term == "return";
    if (fraction && static_cast<double>(row.estimate.events) > row.estimate.exposure) {
      throw InputError(cell(2) +
                       ": a return row's events (returns) cannot exceed its exposure "
                       "(LEAVE attempts), got " +
                       cells.at(2) + " of " + cells.at(3));
    }
    for (const auto& [column, field] :
         {std::pair{4, &row.estimate.rate}, {5, &row.estimate.low}, {6, &row.estimate.high}}) {
      const double value = number(static_cast<std::size_t>(column), true);
      if (fraction && value > 1.0) {
        throw InputError(cell(static_cast<std::size_t>(column)) +
                         ": expected a fraction from 0 to 1 (returns per LEAVE attempt), got '" +
                         cells.at(static_cast<std::size_t>(column)) + "'");
      }
      if (!std::isnan(value)) *field = value;
    }
    if (row.estimate.events > 0 && !(row.estimate.exposure > 0.0)) {
      throw InputError(cell(3) + ": " + cells.at(2) + " events over an exposure of " + cells.at(3) +
                       ": expected an exposure above 0");
    }
    check_rate_is_its_counts(row, cell(4), cells.at(4));
    // A term is written once per model variant that predicts it, on consecutive lines with
    // the same measurement; any other repeat is a second measurement, and which to take is
    // unknown.
    const auto key = std::make_pair(row.term, row.size.value_or(0));
    if (const auto earlier = first_line.find(key); earlier != first_line.end()) {
      const bool continues = rows.back().term == row.term && rows.back().size == row.size;
      if (!continues || !same_measurement(rows.back().estimate, row.estimate)) {
        throw InputError(file.string() + ":" + std::to_string(table.line_of.at(i)) +
                         ": repeats term '" + row.term + "'" +
                         (row.size ? " size " + std::to_string(*row.size) : std::string()) +
                         " of line " + std::to_string(earlier->second) +
                         (continues ? " with another measurement (events, exposure or rate)"
                                    : " after other terms"));
      }
      row = rows.back();
      rows.pop_back();
    } else {
      first_line.emplace(key, table.line_of.at(i));
    }
    if (cells.size() > 9 && !cells[7].empty()) {
      row.models.push_back({cells[7], cells[8], number(9, false)});
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace swarmagg
