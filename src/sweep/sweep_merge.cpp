#include "sweep/sweep_merge.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "analysis/csv_reader.hpp"
#include "analysis/csv_text.hpp"
#include "config/world_keys.hpp"
#include "core/counted.hpp"
#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "output/made_folders.hpp"
#include "output/timeseries_csv.hpp"
#include "plot/run_plots.hpp"
#include "plot/sweep_plots.hpp"
#include "run/interrupt.hpp"
#include "run/recorded_steps.hpp"
#include "run/run_folder.hpp"
#include "sweep/sweep_manifest.hpp"
#include "sweep/sweep_status.hpp"
#include "sweep/sweep_summary.hpp"

namespace swarmagg {
namespace {

constexpr const char* kSweepTimeseriesFile = "sweep_timeseries.csv";
constexpr const char* kSweepPartitionsFile = "sweep_partitions.csv";

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
// read row by row and the merged rows written as they come, so a sweep of long runs merges in
// constant memory (the merged file is the size of all its runs' files together). A row cut
// short, a cell that is not a number, or a count that is not a whole number >= 0 stops the
// merge naming the file, line and column, rather than being copied into the results; the
// unfinished merged file is then discarded.
class MergedCsv {
 public:
  MergedCsv(std::filesystem::path target, const std::vector<std::string>& keys,
            std::string file_header, ColumnKinds kinds)
      : target_(std::move(target)),
        header_(csv_prefix(keys) + file_header + "\n"),
        file_header_(std::move(file_header)),
        kinds_(std::move(kinds)) {}

  // Appends the file's rows; returns its last row's numbers (NaN for text cells; none when
  // it has no rows). With `recorded`, the file is a timeseries of that world's one replicate:
  // each row must be the next state it records (replicate 0, step 0, K, 2K, ... and the last).
  std::vector<double> append(const std::filesystem::path& file, const std::string& prefix,
                             int replicate, const WorldSpec* recorded = nullptr) {
    throw_if_interrupted();
    CsvReader reader(file);
    if (joined(reader.header(), 0) != file_header_) {
      throw InputError(file.string() + ": expected the header '" + file_header_ + "'");
    }
    open();
    const std::string row_prefix = prefix + std::to_string(replicate) + ",";
    std::vector<double> numbers;
    std::int64_t rows = 0;
    while (reader.next()) {
      numbers = checked_numbers(reader, file);
      if (recorded) check_recorded_row(numbers, rows++, *recorded, file, reader.line());
      pending_ += row_prefix + joined(reader.cells(), 1) + "\n";
      if (pending_.size() >= kPieceBytes) {
        flush();
        throw_if_interrupted();  // Ctrl-C, or Slurm's SIGTERM, removes the temporaries
      }
    }
    if (recorded && rows != recorded_rows(*recorded)) {
      throw InputError(file.string() + ": holds " + counted(rows, "row") + " but the run records " +
                       counted(recorded_rows(*recorded), "state") + " (" +
                       counted(recorded->steps(), "step") + ", every " +
                       std::to_string(recorded->run.record_every) + "): cut short; " + redo(file));
    }
    return numbers;
  }

  bool appended() const { return writer_.has_value(); }
  // Once every run is appended: the file is complete and synced, not yet in place.
  void finish() {
    open();  // a file of no rows is its header
    flush();
    writer_->finish();
  }
  void commit() { writer_->commit(); }

 private:
  static constexpr std::size_t kPieceBytes = 1 << 20;

  static std::string redo(const std::filesystem::path& file) {
    return "remove " + file.parent_path().string() + " and run the sweep again to redo it";
  }

  // Row `row` of a sweep run's timeseries: replicate 0 at the row-th state the run records.
  static void check_recorded_row(const std::vector<double>& numbers, std::int64_t row,
                                 const WorldSpec& world, const std::filesystem::path& file,
                                 std::int64_t line) {
    // The file and line are named only when a row is refused: every row of a sweep passes here.
    const auto at = [&] { return file.string() + ":" + std::to_string(line) + ": "; };
    if (row >= recorded_rows(world)) {
      throw InputError(at() + "a row after the run's last recorded state (step " +
                       std::to_string(world.steps()) + "): a row repeated or added; " + redo(file));
    }
    const std::int64_t step = std::min(row * world.run.record_every, world.steps());
    if (numbers[0] == 0.0 && numbers[1] == static_cast<double>(step)) return;
    throw InputError(at() + "expected replicate 0 at step " + std::to_string(step) +
                     " (the run records every " + std::to_string(world.run.record_every) +
                     " steps and its last, " + std::to_string(world.steps()) + "), got replicate " +
                     csv_number(numbers[0]) + " at step " + csv_number(numbers[1]) +
                     ": a row missing, repeated or edited; " + redo(file));
  }

  void open() {
    if (writer_) return;
    writer_.emplace(target_);
    pending_ = header_;
  }
  void flush() {
    writer_->write(pending_);
    pending_.clear();
  }

  std::vector<double> checked_numbers(const CsvReader& reader,
                                      const std::filesystem::path& file) const {
    const std::vector<std::string>& header = reader.header();
    std::vector<double> numbers(header.size(), std::nan(""));
    for (std::size_t column = 0; column < header.size(); ++column) {
      if (listed(kinds_.text, column)) continue;
      const double value = reader.number(column);  // names the file, line and column
      const bool count = !listed(kinds_.real, column);
      if (!std::isfinite(value) || (count && !(value >= 0.0 && value == std::floor(value)))) {
        throw InputError(file.string() + ":" + std::to_string(reader.line()) + ": column '" +
                         header[column] + "': expected " +
                         (count ? "a whole number >= 0" : "a finite number") + ", got '" +
                         reader.cell(column) + "'");
      }
      numbers[column] = value;
    }
    return numbers;
  }

  std::filesystem::path target_;
  std::string header_;  // the merged file's
  std::string file_header_;
  ColumnKinds kinds_;
  std::optional<AtomicFileWriter> writer_;  // from the first file appended
  std::string pending_;                     // rows not yet written
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

// The observables of a run's last timeseries row (after replicate, step and time).
std::vector<double> final_observables(const std::vector<double>& last_row) {
  return {last_row.begin() + 3, last_row.end()};
}

std::vector<std::string> observable_names() {
  std::vector<std::string> names = split(kTimeseriesHeader, ',');
  names.erase(names.begin(), names.begin() + 3);
  return names;
}

// A folder merge writes into without --force holds no run (its plots and tables would sit
// beside the sweep's) and no other sweep (the merged tables would be replaced). Anything else
// may stay: the shards' own folders and a cluster's logs (examples/slurm/submit.sh merges
// results/shard-* into results/).
void check_merge_folder(const std::filesystem::path& out, const SweepPlan& plan) {
  std::error_code error;
  if (std::filesystem::exists(out / kManifestFile, error)) {
    const SweepPlan earlier = read_manifest(out);
    if (earlier.name == plan.name) return;
    throw InputError(out.string() + "/ holds the sweep '" + earlier.name + "', not '" + plan.name +
                     "': pass --force to replace its merged files, or --out DIR");
  }
  if (std::filesystem::exists(out / "world.resolved.yaml", error)) {
    throw InputError(out.string() +
                     "/ holds a run (world.resolved.yaml): pass --force to merge the sweep "
                     "beside it, or --out DIR");
  }
}

// What an earlier merge in `out` left that this one may outdate: its plots (drawn from its
// sweep_summary.csv, by its parameters' keys) and its partitions.
struct EarlierMerge {
  std::vector<std::string> keys;
  std::string summary;  // sweep_summary.csv's text
};

// The plots were drawn from sweep_summary.csv, named by its parameter columns (those before
// `observable`), as draw_sweep_plots names them; only world keys, so that no file name can
// leave the folder (an edited "../x" column).
std::optional<EarlierMerge> earlier_merge(const std::filesystem::path& out) {
  std::ifstream in(out / kSweepSummaryFile, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  EarlierMerge earlier{{}, text.str()};
  const std::string header = earlier.summary.substr(0, earlier.summary.find('\n'));
  for (const std::string& column : split(header, ',')) {
    if (column == "observable") break;
    if (find_world_key(column) != nullptr) earlier.keys.push_back(column);
  }
  return earlier;
}

// The earlier merge's plots drew another summary (another sweep, or fewer runs): they go,
// for `swarmagg plot` (or the sweep itself) to draw the new one; a plot of the same summary
// stays. So does nothing else in the folder. An earlier merge's partitions go when this one
// has none. Returns what was removed.
std::vector<std::filesystem::path> remove_outdated(const std::filesystem::path& out,
                                                   const std::optional<EarlierMerge>& earlier,
                                                   const std::string& summary,
                                                   bool has_partitions) {
  std::vector<std::filesystem::path> removed;
  std::error_code error;
  const auto remove = [&](const std::filesystem::path& file) {
    if (std::filesystem::remove(file, error)) removed.push_back(file);
  };
  if (!has_partitions) remove(out / kSweepPartitionsFile);
  if (!earlier || earlier->summary == summary) return removed;
  for (const std::string& key : earlier->keys) {
    const FigureFiles files = sweep_plot_files(out, key);
    for (const std::filesystem::path& file : {files.png(), files.script(), files.csv("")})
      remove(file);
  }
  return removed;
}

}  // namespace

MergeReport merge_sweep(const std::vector<std::filesystem::path>& folders,
                        const std::filesystem::path& out, bool force) {
  const SweepPlan plan = common_plan(folders);
  if (!force) check_merge_folder(out, plan);
  const std::optional<EarlierMerge> earlier = earlier_merge(out);
  const std::vector<SweepRun> runs = expand_sweep(plan);
  const std::vector<std::filesystem::path> locations = run_locations(runs, folders);
  const std::vector<std::string> keys = parameter_keys(plan);
  // A merge refused on the way (a damaged shard file) leaves no folder it made; the merged
  // files' temporaries are removed first (declared after).
  const MadeFolders made(out);
  const RemovedOnFailure unmade(made);
  // A merge killed outright (SIGKILL) leaves its temporaries: a dead process's, removed.
  remove_stale_temporaries(out);
  // Every timeseries column counts something but the time.
  MergedCsv timeseries(out / kSweepTimeseriesFile, keys, kTimeseriesHeader,
                       {.real = {2}, .text = {}});
  // partitions_csv of no replicates is exactly the header run folders carry.
  // replicate, partition ("4+2+1"), time_fraction.
  MergedCsv partitions(out / kSweepPartitionsFile, keys,
                       split(partitions_csv(RunResult{}, 1), '\n').front(),
                       {.real = {2}, .text = {1}});
  std::vector<PointFinals> finals;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const SweepRun& run = runs[i];
    if (run.replicate == 0) finals.push_back({point_values(run.point), {}});
    const std::string prefix = csv_prefix(finals.back().values);
    const auto file = locations[i] / "timeseries.csv";
    const std::vector<double> last = timeseries.append(file, prefix, run.replicate, &run.world);
    finals.back().replicates.push_back(final_observables(last));
    if (std::filesystem::exists(locations[i] / "partitions.csv")) {
      partitions.append(locations[i] / "partitions.csv", prefix, run.replicate);
    }
  }
  MergeReport report{static_cast<int>(finals.size()), static_cast<int>(runs.size()), {}, {}, false};
  // Every file complete and synced before the first takes its place: a full disk fails them
  // all, and a merge stopped before the first rename leaves the earlier merged files as they
  // were (not transactional: a rename failing after it would leave old and new side by side).
  timeseries.finish();
  if (partitions.appended()) partitions.finish();
  timeseries.commit();
  report.files.push_back(out / kSweepTimeseriesFile);
  if (partitions.appended()) {
    partitions.commit();
    report.files.push_back(out / kSweepPartitionsFile);
  }
  auto write = [&](const std::string& name, const std::string& text) {
    write_file_atomic(out / name, text);
    report.files.push_back(out / name);
  };
  const std::string summary = sweep_summary_csv(keys, observable_names(), finals);
  write(kSweepSummaryFile, summary);
  write(kManifestFile, manifest_text(plan));
  report.removed = remove_outdated(out, earlier, summary, partitions.appended());
  report.plots_removed = std::any_of(
      report.removed.begin(), report.removed.end(),
      [](const std::filesystem::path& file) { return file.filename() != kSweepPartitionsFile; });
  return report;
}

}  // namespace swarmagg
