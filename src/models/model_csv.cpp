#include "models/model_csv.hpp"

#include <charconv>
#include <cstdio>
#include <map>
#include <string_view>

#include "models/sample_statistics.hpp"

namespace swarmagg {

namespace {

// Shortest text that reads back as the same double.
void append_number(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

// step * dt with 12 significant digits, so 3 * 0.1 prints as 0.3.
void append_time(std::string& out, std::int64_t step, double dt) {
  char buffer[32];
  const int length = std::snprintf(buffer, sizeof buffer, "%.12g", static_cast<double>(step) * dt);
  out.append(buffer, static_cast<std::size_t>(length));
}

void append_tidy_row(std::string& out, const VariantPrediction& prediction,
                     std::optional<std::int64_t> step, double dt, std::string_view quantity,
                     double value) {
  out += prediction.model;
  out += ',';
  out += prediction.variant;
  out += ',';
  if (step) out += std::to_string(*step);
  out += ',';
  if (step) append_time(out, *step, dt);
  out += ',';
  out += quantity;
  out += ',';
  append_number(out, value);
  out += '\n';
}

bool has_box_plot(std::string_view column) { return column == "noa" || column == "encounters"; }

void append_replicate_statistics(std::string& out, const VariantPrediction& prediction,
                                 std::int64_t step, double dt, std::string_view column,
                                 const std::vector<double>& values) {
  const std::string name(column);
  append_tidy_row(out, prediction, step, dt, name, sample_mean(values));
  append_tidy_row(out, prediction, step, dt, name + ":sd", sample_sd(values));
  if (!has_box_plot(column)) return;
  constexpr std::pair<const char*, double> kBoxPlot[] = {
      {":min", 0.0}, {":q25", 0.25}, {":median", 0.5}, {":q75", 0.75}, {":max", 1.0}};
  for (const auto& [suffix, q] : kBoxPlot) {
    append_tidy_row(out, prediction, step, dt, name + suffix, sample_quantile(values, q));
  }
}

void append_expected_series(std::string& out, const VariantPrediction& prediction, double dt) {
  for (const TimeseriesRow& row : prediction.series) {
    for (const TimeseriesColumn& column : kTimeseriesColumns) {
      if (const auto& value = row.*column.field) {
        append_tidy_row(out, prediction, row.step, dt, column.name, *value);
      }
    }
  }
}

void append_stochastic_series(std::string& out, const VariantPrediction& prediction, double dt) {
  std::map<std::int64_t, std::vector<const TimeseriesRow*>> replicates_at;
  for (const TimeseriesRow& row : prediction.series) replicates_at[row.step].push_back(&row);
  for (const auto& [step, rows] : replicates_at) {
    for (const TimeseriesColumn& column : kTimeseriesColumns) {
      std::vector<double> values;
      for (const TimeseriesRow* row : rows) {
        if (const auto& value = row->*column.field) values.push_back(*value);
      }
      if (!values.empty()) {
        append_replicate_statistics(out, prediction, step, dt, column.name, values);
      }
    }
  }
}

}  // namespace

std::string model_csv(const std::vector<VariantPrediction>& predictions, double dt) {
  std::string out = "model,variant,step,time,quantity,value\n";
  for (const VariantPrediction& prediction : predictions) {
    if (prediction.stochastic) {
      append_stochastic_series(out, prediction, dt);
    } else {
      append_expected_series(out, prediction, dt);
    }
    for (const TidyValue& value : prediction.extra) {
      append_tidy_row(out, prediction, value.step, dt, value.quantity, value.value);
    }
  }
  return out;
}

std::string timeseries_csv(const VariantPrediction& prediction, double dt) {
  std::string out = "replicate,step,time";
  for (const TimeseriesColumn& column : kTimeseriesColumns) {
    out += ',';
    out += column.name;
  }
  out += '\n';
  for (const TimeseriesRow& row : prediction.series) {
    out += std::to_string(row.replicate);
    out += ',';
    out += std::to_string(row.step);
    out += ',';
    append_time(out, row.step, dt);
    for (const TimeseriesColumn& column : kTimeseriesColumns) {
      out += ',';
      if (const auto& value = row.*column.field) append_number(out, *value);
    }
    out += '\n';
  }
  return out;
}

}  // namespace swarmagg
