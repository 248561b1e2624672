#include "sweep/sweep_merge.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/csv_table.hpp"
#include "analysis/csv_text.hpp"
#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "output/timeseries_csv.hpp"
#include "run/run_folder.hpp"
#include "sweep/sweep_manifest.hpp"
#include "sweep/sweep_status.hpp"
#include "sweep/sweep_summary.hpp"

namespace swarmagg {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  for (std::size_t end; (end = text.find(separator, begin)) != std::string::npos; begin = end + 1) {
    parts.push_back(text.substr(begin, end - begin));
  }
  parts.push_back(text.substr(begin));
  return parts;
}

std::string csv_prefix(const std::vector<std::string>& fields) {
  std::string text;
  for (const std::string& field : fields) text += field + ",";
  return text;
}

std::vector<std::string> parameter_keys(const SweepPlan& plan) {
  std::vector<std::string> keys;
  for (const SweepParameter& p : plan.parameters) keys.push_back(p.key);
  return keys;
}

std::vector<std::string> point_values(const SweepPoint& point) {
  std::vector<std::string> values;
  for (const auto& assignment : point.assignments) values.push_back(assignment.second);
  return values;
}

std::string joined(const std::vector<std::string>& fields, std::size_t from) {
  std::string text;
  for (std::size_t k = from; k < fields.size(); ++k) text += (k > from ? "," : "") + fields[k];
  return text;
}

// What a merged file's cells hold: counts unless a column is listed as real or as text.
struct ColumnKinds {
  std::vector<std::size_t> real;
  std::vector<std::size_t> text;
};

bool listed(const std::vector<std::size_t>& columns, std::size_t column) {
  return std::find(columns.begin(), columns.end(), column) != columns.end();
}

// One merged CSV: the parameter columns, then a run file's columns, whose first column is
// the replicate (always 0 in a sweep run's folder: a run is one replicate). Shard files are
// read as tables: a row cut short, a cell that is not a number, or a count that is not a whole
// number >= 0 stops the merge naming the file, line and column, rather than being copied into
// the results.
class MergedCsv {
 public:
  MergedCsv(const std::vector<std::string>& keys, std::string file_header, ColumnKinds kinds)
      : file_header_(std::move(file_header)),
        kinds_(std::move(kinds)),
        text_(csv_prefix(keys) + file_header_ + "\n") {}

  // Appends the file's rows; returns its last row's numbers (NaN for text cells; none when
  // it has no rows).
  std::vector<double> append(const std::filesystem::path& file, const std::string& prefix,
                             int replicate) {
    const CsvTable table = read_csv(file);
    if (joined(table.header, 0) != file_header_) {
      throw InputError(file.string() + ": expected the header '" + file_header_ + "'");
    }
    std::vector<double> numbers;
    for (std::size_t row = 0; row < table.rows.size(); ++row) {
      numbers = checked_numbers(table, row);
      text_ += prefix + std::to_string(replicate) + "," + joined(table.rows[row], 1) + "\n";
    }
    appended_ = true;
    return numbers;
  }

  bool appended() const { return appended_; }
  const std::string& text() const { return text_; }

 private:
  std::vector<double> checked_numbers(const CsvTable& table, std::size_t row) const {
    std::vector<double> numbers(table.header.size(), std::nan(""));
    for (std::size_t column = 0; column < table.header.size(); ++column) {
      if (listed(kinds_.text, column)) continue;
      const double value = table.number(row, column);  // names the file, line and column
      const bool count = !listed(kinds_.real, column);
      if (!std::isfinite(value) || (count && !(value >= 0.0 && value == std::floor(value)))) {
        throw InputError(table.source + ":" + std::to_string(table.line_of.at(row)) + ": column '" +
                         table.header[column] + "': expected " +
                         (count ? "a whole number >= 0" : "a finite number") + ", got '" +
                         table.rows[row][column] + "'");
      }
      numbers[column] = value;
    }
    return numbers;
  }

  std::string file_header_;
  ColumnKinds kinds_;
  std::string text_;
  bool appended_ = false;
};

SweepPlan common_plan(const std::vector<std::filesystem::path>& folders) {
  if (folders.empty()) throw InputError("merge: name at least one sweep output folder");
  const SweepPlan plan = read_manifest(folders.front());
  const std::string manifest = manifest_text(plan);
  for (const std::filesystem::path& folder : folders) {
    if (manifest_text(read_manifest(folder)) != manifest) {
      throw InputError(folder.string() + ": holds a different sweep than " +
                       folders.front().string() + " (their " + kManifestFile + " differ)");
    }
  }
  return plan;
}

// The folder holding each run complete (the first that does, in the order given).
std::vector<std::filesystem::path> run_locations(
    const std::vector<SweepRun>& runs, const std::vector<std::filesystem::path>& folders) {
  std::vector<std::filesystem::path> found;
  std::vector<const SweepRun*> missing;
  for (const SweepRun& run : runs) {
    found.emplace_back();
    for (const std::filesystem::path& folder : folders) {
      if (sweep_run_status(folder, run) == RunStatus::Complete) {
        found.back() = sweep_run_folder(folder, run);
        break;
      }
    }
    if (found.back().empty()) missing.push_back(&run);
  }
  if (missing.empty()) return found;
  const SweepRun& first = *missing.front();
  throw InputError(
      "merge: " + std::to_string(missing.size()) + " of " + std::to_string(runs.size()) +
      " runs are not complete in any folder given, e.g. run " + std::to_string(first.index) + " (" +
      describe_point(first.point) + ", replicate " + std::to_string(first.replicate) +
      "); run the missing shards (or resume the sweep) first");
}

// A run's timeseries ends with its last step: one cut short at a line's end reads as a
// complete file whose last row is an earlier state.
void check_reaches_the_end(const std::vector<double>& last_row, const WorldSpec& world,
                           const std::filesystem::path& file) {
  if (last_row.empty()) throw InputError(file.string() + ": holds no rows");
  const double last_step = last_row[1];
  if (last_step != static_cast<double>(world.steps())) {
    throw InputError(file.string() + ": ends at step " + csv_number(last_step) +
                     " but the run has " + std::to_string(world.steps()) +
                     " steps (cut short?); remove " + file.parent_path().string() +
                     " and run the sweep again to redo it");
  }
}

// The observables of a run's last timeseries row (after replicate, step and time).
std::vector<double> final_observables(const std::vector<double>& last_row) {
  return {last_row.begin() + 3, last_row.end()};
}

std::vector<std::string> observable_names() {
  std::vector<std::string> names = split(kTimeseriesHeader, ',');
  names.erase(names.begin(), names.begin() + 3);
  return names;
}

}  // namespace

MergeReport merge_sweep(const std::vector<std::filesystem::path>& folders,
                        const std::filesystem::path& out) {
  const SweepPlan plan = common_plan(folders);
  const std::vector<SweepRun> runs = expand_sweep(plan);
  const std::vector<std::filesystem::path> locations = run_locations(runs, folders);
  const std::vector<std::string> keys = parameter_keys(plan);
  // Every timeseries column counts something but the time.
  MergedCsv timeseries(keys, kTimeseriesHeader, {.real = {2}, .text = {}});
  // partitions_csv of no replicates is exactly the header run folders carry.
  // replicate, partition ("4+2+1"), time_fraction.
  MergedCsv partitions(keys, split(partitions_csv(RunResult{}, 1), '\n').front(),
                       {.real = {2}, .text = {1}});
  std::vector<PointFinals> finals;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const SweepRun& run = runs[i];
    if (run.replicate == 0) finals.push_back({point_values(run.point), {}});
    const std::string prefix = csv_prefix(finals.back().values);
    const auto file = locations[i] / "timeseries.csv";
    const std::vector<double> last = timeseries.append(file, prefix, run.replicate);
    check_reaches_the_end(last, run.world, file);
    finals.back().replicates.push_back(final_observables(last));
    if (std::filesystem::exists(locations[i] / "partitions.csv")) {
      partitions.append(locations[i] / "partitions.csv", prefix, run.replicate);
    }
  }
  MergeReport report{static_cast<int>(finals.size()), static_cast<int>(runs.size()), {}};
  auto write = [&](const std::string& name, const std::string& text) {
    write_file_atomic(out / name, text);
    report.files.push_back(out / name);
  };
  write("sweep_timeseries.csv", timeseries.text());
  if (partitions.appended()) write("sweep_partitions.csv", partitions.text());
  write("sweep_summary.csv", sweep_summary_csv(keys, observable_names(), finals));
  write(kManifestFile, manifest_text(plan));
  return report;
}

}  // namespace swarmagg
