#include "sweep/sweep_merge.hpp"

#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

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

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
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

// One merged CSV: the parameter columns, then a run file's columns, whose first column is
// the replicate (always 0 in a sweep run's folder: a run is one replicate).
class MergedCsv {
 public:
  MergedCsv(const std::vector<std::string>& keys, std::string file_header)
      : file_header_(std::move(file_header)), text_(csv_prefix(keys) + file_header_ + "\n") {}

  // Appends the file's rows; returns its last row.
  std::string append(const std::filesystem::path& file, const std::string& prefix, int replicate) {
    const std::vector<std::string> lines = split(read_text(file), '\n');
    if (lines.front() != file_header_) {
      throw std::runtime_error(file.string() + ": expected the header '" + file_header_ + "'");
    }
    std::string last;
    for (std::size_t i = 1; i < lines.size(); ++i) {
      if (lines[i].empty()) continue;
      last = lines[i];
      text_ += prefix + std::to_string(replicate) + lines[i].substr(lines[i].find(',')) + "\n";
    }
    appended_ = true;
    return last;
  }

  bool appended() const { return appended_; }
  const std::string& text() const { return text_; }

 private:
  std::string file_header_;
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

std::vector<double> final_observables(const std::string& last_row,
                                      const std::filesystem::path& file) {
  std::vector<double> values;
  const std::vector<std::string> fields = split(last_row, ',');
  if (fields.size() != split(kTimeseriesHeader, ',').size()) {
    throw std::runtime_error(file.string() + ": malformed or missing last row '" + last_row + "'");
  }
  for (std::size_t k = 3; k < fields.size(); ++k) {  // after replicate, step, time
    double value = 0.0;
    const auto [end, error] =
        std::from_chars(fields[k].data(), fields[k].data() + fields[k].size(), value);
    if (error != std::errc() || end != fields[k].data() + fields[k].size()) {
      throw std::runtime_error(file.string() + ": malformed last row '" + last_row + "'");
    }
    values.push_back(value);
  }
  return values;
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
  MergedCsv timeseries(keys, kTimeseriesHeader);
  // partitions_csv of no replicates is exactly the header run folders carry.
  MergedCsv partitions(keys, split(partitions_csv(RunResult{}, 1), '\n').front());
  std::vector<PointFinals> finals;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const SweepRun& run = runs[i];
    if (run.replicate == 0) finals.push_back({point_values(run.point), {}});
    const std::string prefix = csv_prefix(finals.back().values);
    const auto file = locations[i] / "timeseries.csv";
    const std::string last = timeseries.append(file, prefix, run.replicate);
    finals.back().replicates.push_back(final_observables(last, file));
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
