#include "run/model_outputs.hpp"

#include <fstream>
#include <functional>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <string_view>

#include "models/model_csv.hpp"
#include "output/atomic_file.hpp"
#include "output/made_folders.hpp"
#include "run/interrupt.hpp"
#include "run/model_progress.hpp"

namespace swarmagg {

namespace {

// The variant files of the model.csv in `out` (model-timeseries/<model>-<variant>.csv), read
// leniently: the file may be damaged or of another version.
std::set<std::string> earlier_variant_files(const std::filesystem::path& out) {
  std::set<std::string> files;
  std::ifstream in(out / "model.csv");
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    const std::size_t model_end = line.find(',');
    if (model_end == std::string::npos) continue;
    const std::size_t variant_end = line.find(',', model_end + 1);
    if (variant_end == std::string::npos) continue;
    const std::string file = line.substr(0, model_end) + "-" +
                             line.substr(model_end + 1, variant_end - model_end - 1) + ".csv";
    // A name that is not one file of model-timeseries/ is no variant of ours.
    if (file.find('/') == std::string::npos && !file.starts_with(".")) files.insert(file);
  }
  return files;
}

std::string variant_file(const VariantPrediction& variant) {
  return variant.model + "-" + variant.variant + ".csv";
}

// Keeps `row` when no later step was kept: the rows of the last step remain, one per
// replicate.
void keep_if_latest(std::vector<ModelRow>& kept, const ModelRow& row) {
  if (!kept.empty() && row.step < kept.front().step) return;
  if (!kept.empty() && row.step > kept.front().step) kept.clear();
  kept.push_back(row);
}

// Where a variant's text goes, piece by piece: model.csv, and its model-timeseries file
// (none when only model.csv is wanted).
using TextSink = std::function<void(std::string_view piece)>;

// One variant's lines of model.csv and its model-timeseries file, each written as its rows
// are walked: a stochastic variant's statistics need the replicates side by side, its file
// lists them one after another, so it is walked twice.
VariantPrediction write_variant(const PendingVariant& variant, const TextSink& model_csv,
                                const TextSink& series, double dt, const WalkProgress& progress) {
  VariantPrediction written = variant.header;
  std::string text;
  const auto write_text = [&](const TextSink& sink) {
    sink(text);
    text.clear();
  };
  if (written.stochastic) {
    std::vector<const ModelRow*> rows_at_step;
    variant.walk_steps(
        [&](std::span<const ModelRow> rows) {
          rows_at_step.clear();
          for (const ModelRow& row : rows) rows_at_step.push_back(&row);
          append_replicate_statistics(text, written, rows_at_step, dt);
          write_text(model_csv);
        },
        progress);
  }
  if (series) series(model_timeseries_header());
  written.extra = variant.walk_rows(
      [&](const ModelRow& row) {
        if (!written.stochastic) {
          append_expected_row(text, written, row, dt);
          write_text(model_csv);
        }
        if (series) {
          append_timeseries_row(text, row, dt);
          write_text(series);
        }
        keep_if_latest(written.series, row);
      },
      progress, Extras::Computed);
  append_extra_values(text, written, dt);
  write_text(model_csv);
  return written;
}

TextSink into(AtomicFileWriter& file) {
  return [&file](std::string_view piece) { file.write(piece); };
}

}  // namespace

std::vector<VariantPrediction> write_model_outputs(const WorldSpec& spec,
                                                   const std::vector<PendingVariant>& variants,
                                                   const std::filesystem::path& out,
                                                   bool show_progress) {
  const std::filesystem::path series = out / "model-timeseries";
  const MadeFolders made(series);
  std::set<std::string> stale = earlier_variant_files(out);
  double work = 0.0;
  for (const PendingVariant& variant : variants)
    work += variant.walk_rows_work + variant.walk_steps_work;
  ModelProgress progress(spec.name, static_cast<int>(variants.size()), work, show_progress);
  const WalkProgress walk_progress = [&](std::int64_t steps) { progress.add_work(steps); };
  std::vector<VariantPrediction> written;
  try {
    AtomicFileWriter model_csv(out / "model.csv");
    model_csv.write(kModelCsvHeader);
    std::vector<std::unique_ptr<AtomicFileWriter>> series_files;
    for (const PendingVariant& variant : variants) {
      const std::string file = variant_file(variant.header);
      series_files.push_back(std::make_unique<AtomicFileWriter>(series / file));
      written.push_back(write_variant(variant, into(model_csv), into(*series_files.back()),
                                      spec.engine.dt, walk_progress));
      progress.finished_variant();
      stale.erase(file);
    }
    // All on disk before the first lands, so a full disk fails them all; model.csv, which
    // lists the variants, lands last.
    for (const auto& file : series_files) file->finish();
    model_csv.finish();
    for (const auto& file : series_files) file->commit();
    model_csv.commit();
  } catch (...) {
    progress.finish();
    // The writers have removed their temporaries; folders made for them go too (when empty).
    made.remove_if_empty();
    throw;
  }
  progress.finish();
  // A variant the earlier model of the folder had (`measured`, say) would stay beside these;
  // files of yours in model-timeseries/ stay.
  std::error_code error;
  for (const std::string& file : stale) std::filesystem::remove(series / file, error);
  // A controller without a model has no variant files: no empty folder for them (remove()
  // leaves a folder that still holds something).
  if (variants.empty()) std::filesystem::remove(series, error);
  return written;
}

std::string model_csv_text(const WorldSpec& spec, const std::vector<PendingVariant>& variants) {
  std::string text = kModelCsvHeader;
  const TextSink append = [&text](std::string_view piece) { text += piece; };
  const WalkProgress check_interrupt = [](std::int64_t) { throw_if_interrupted(); };
  for (const PendingVariant& variant : variants)
    write_variant(variant, append, nullptr, spec.engine.dt, check_interrupt);
  return text;
}

}  // namespace swarmagg
