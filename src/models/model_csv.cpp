#include "models/model_csv.hpp"

#include <charconv>
#include <map>
#include <string_view>

#include "core/time_text.hpp"
#include "models/sample_statistics.hpp"

namespace swarmagg {

namespace {

// Shortest text that reads back as the same double.
void append_number(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_time(std::string& out, std::int64_t step, double dt) {
  out += time_text(static_cast<double>(step) * dt);
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

// model.csv keeps to what is plotted against simulations, so a 50000-step world stays a
// few MB; every column of every replicate is in the model timeseries files.
enum class Statistics { None, MeanSd, BoxPlot };

bool in_expected_rows(std::string_view column) {
  return column != "waiting";
}  // N - searching

Statistics stochastic_statistics(std::string_view column) {
  if (column == "noa" || column == "encounters") return Statistics::BoxPlot;
  if (column == "searching" || column == "largest") return Statistics::MeanSd;
  return Statistics::None;
}

void append_column_statistics(std::string& out, const VariantPrediction& prediction,
                              std::int64_t step, double dt, std::string_view column,
                              const std::vector<double>& values) {
  const Statistics statistics = stochastic_statistics(column);
  if (statistics == Statistics::None) return;
  const std::string name(column);
  append_tidy_row(out, prediction, step, dt, name, sample_mean(values));
  append_tidy_row(out, prediction, step, dt, name + ":sd", sample_sd(values));
  if (statistics != Statistics::BoxPlot) return;
  constexpr std::pair<const char*, double> kBoxPlot[] = {
      {":min", 0.0}, {":q25", 0.25}, {":median", 0.5}, {":q75", 0.75}, {":max", 1.0}};
  for (const auto& [suffix, q] : kBoxPlot) {
    append_tidy_row(out, prediction, step, dt, name + suffix, sample_quantile(values, q));
  }
}

}  // namespace

void append_expected_row(std::string& out, const VariantPrediction& variant, const ModelRow& row,
                         double dt) {
  for (const ModelColumn& column : kModelColumns) {
    const auto& value = row.*column.field;
    if (value && in_expected_rows(column.name)) {
      append_tidy_row(out, variant, row.step, dt, column.name, *value);
    }
  }
}

void append_replicate_statistics(std::string& out, const VariantPrediction& variant,
                                 std::span<const ModelRow* const> rows, double dt) {
  if (rows.empty()) return;
  for (const ModelColumn& column : kModelColumns) {
    std::vector<double> values;
    for (const ModelRow* row : rows) {
      if (const auto& value = row->*column.field) values.push_back(*value);
    }
    if (!values.empty()) {
      append_column_statistics(out, variant, rows.front()->step, dt, column.name, values);
    }
  }
}

void append_extra_values(std::string& out, const VariantPrediction& variant, double dt) {
  for (const TidyValue& value : variant.extra) {
    append_tidy_row(out, variant, value.step, dt, value.quantity, value.value);
  }
}

std::string model_timeseries_header() {
  std::string out = "replicate,step,time";
  for (const ModelColumn& column : kModelColumns) {
    out += ',';
    out += column.name;
  }
  out += '\n';
  return out;
}

void append_timeseries_row(std::string& out, const ModelRow& row, double dt) {
  out += std::to_string(row.replicate);
  out += ',';
  out += std::to_string(row.step);
  out += ',';
  append_time(out, row.step, dt);
  for (const ModelColumn& column : kModelColumns) {
    out += ',';
    if (const auto& value = row.*column.field) append_number(out, *value);
  }
  out += '\n';
}

std::string model_csv(const std::vector<VariantPrediction>& predictions, double dt) {
  std::string out = kModelCsvHeader;
  for (const VariantPrediction& prediction : predictions) {
    if (prediction.stochastic) {
      std::map<std::int64_t, std::vector<const ModelRow*>> replicates_at;
      for (const ModelRow& row : prediction.series) replicates_at[row.step].push_back(&row);
      for (const auto& [step, rows] : replicates_at)
        append_replicate_statistics(out, prediction, rows, dt);
    } else {
      for (const ModelRow& row : prediction.series) append_expected_row(out, prediction, row, dt);
    }
    append_extra_values(out, prediction, dt);
  }
  return out;
}

std::string model_timeseries_csv(const VariantPrediction& prediction, double dt) {
  std::string out = model_timeseries_header();
  for (const ModelRow& row : prediction.series) append_timeseries_row(out, row, dt);
  return out;
}

}  // namespace swarmagg
