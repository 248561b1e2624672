// swarmagg.run() and swarmagg.rates(): the replicates of a world in the CLI's thread pool,
// without the GIL. The outputs come back as the texts `swarmagg run` writes (timeseries.csv,
// summary.json, model.csv, partitions.csv, rates.csv, rates.json), made by the same
// functions, so a frame read from them equals the file.
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>

#include "analysis/model_errors.hpp"
#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"
#include "models/model_csv.hpp"
#include "models/predictions.hpp"
#include "output/scratch_folder.hpp"
#include "output/timeseries_csv.hpp"
#include "python/bindings.hpp"
#include "python/bound_class.hpp"
#include "python/interruptible.hpp"
#include "python/world.hpp"
#include "rates/rate_rows.hpp"
#include "rates/rates_csv.hpp"
#include "rates/rates_json.hpp"
#include "run/measured_run.hpp"
#include "run/model_outputs.hpp"
#include "run/partition_recording.hpp"
#include "run/placement_sample.hpp"
#include "run/run_folder.hpp"

namespace py = pybind11;

namespace swarmagg::python {
namespace {

class RunOutput {
 public:
  using BoundToPython = void;

  RunOutput(World world, MeasuredRun run)
      : spec_(world.spec),
        changes_(std::move(world.changes)),
        run_(std::move(run)),
        start_(placement_start_or_reason(*spec_, 0, no_start_)) {
    if (run_.rates)
      rate_rows_ = measured_rate_rows(*spec_, *run_.rates, start_ ? &*start_ : nullptr);
  }

  World world() const { return {spec_, changes_}; }
  std::string timeseries_csv_text() const { return timeseries_csv(all_rows(run_.result)); }
  // summary.json as `swarmagg run` leaves it: its overrides, and the model errors it adds from
  // the run folder's files, here from a scratch folder of the same files.
  std::string summary_json() const {
    nlohmann::json summary = run_summary(*spec_, run_.result, changes_);
    summary["model_errors"] = call_interruptibly([&] { return model_errors(); });
    return summary.dump();
  }
  std::string partitions_csv_text() const {
    if (!controller_rules(*spec_).records_partitions) {
      throw InputError("partitions: the world's controller (" + spec_->controller.type +
                       ") records no partitions; Soysal worlds do");
    }
    if (!records_partitions(*spec_)) {
      throw InputError(
          "partitions: recorded for Soysal worlds of at most 30 agents (the "
          "partition model's largest); this one has " +
          std::to_string(spec_->robots.count));
    }
    return partitions_csv(run_.result, spec_->steps());
  }
  // model.csv of `swarmagg run`: with the measured variants when the run measured rates.
  std::string model_csv_text() const {
    const std::optional<MeasuredTerms> terms = run_terms();
    return call_interruptibly([&] {
      return swarmagg::model_csv_text(
          *spec_, pending_predictions(*spec_, terms ? &*terms : nullptr, start()));
    });
  }
  bool measured() const { return run_.rates.has_value(); }
  std::string rates_csv_text() const { return rates_csv(rows()); }
  std::string rates_json_text() const { return rates_json(*spec_, *run_.rates, rows()); }

 private:
  const std::vector<RateRow>& rows() const {
    if (!run_.rates) throw InputError("rates: this run measured no rates; run it with rates=True");
    return rate_rows_;
  }

  // The models' start (run/placement_sample.hpp); the reason it could not be sampled, as the
  // error of whatever needs it.
  const PlacementSample* start() const {
    if (!no_start_.empty()) throw InputError(no_start_);
    return start_ ? &*start_ : nullptr;
  }

  std::optional<MeasuredTerms> run_terms() const {
    if (!run_.rates) return std::nullopt;
    return measured_terms(rate_rows_);
  }

  nlohmann::json model_errors() const {
    const ScratchFolder folder("swarmagg-py");
    write_run_folder(*spec_, run_.result, folder.path());
    try {
      const std::optional<MeasuredTerms> terms = run_terms();
      write_model_outputs(*spec_, pending_predictions(*spec_, terms ? &*terms : nullptr, start()),
                          folder.path());
    } catch (const InputError&) {
      return nlohmann::json::array();  // a world without a model: the CLI writes none either
    }
    return model_errors_json(run_model_errors(folder.path()));
  }

  std::shared_ptr<const WorldSpec> spec_;
  std::vector<std::string> changes_;
  MeasuredRun run_;
  std::string no_start_;  // declared before start_, which is initialised with it
  std::optional<PlacementSample> start_;
  std::vector<RateRow> rate_rows_;
};

// Integers as Python objects, read as `seed` is (yaml_index): a bool is a TypeError, a number
// beyond 64 bits or the key's range a ValueError, as for every other argument.
RunOutput run(const World& world, std::optional<py::object> replicates,
              std::optional<py::object> seed, std::optional<py::object> threads,
              std::optional<std::string> engine, bool rates) {
  std::vector<WorldOverride> overrides;
  add_argument(overrides, "engine.type", engine, "engine");
  add_argument(overrides, "run.replicates", replicates, "replicates");
  add_argument(overrides, "run.seed", seed, "seed");
  add_argument(overrides, "run.threads", threads, "threads");
  const World ran = with_overrides(world, overrides);
  // Results stay in memory: a world asking for files would otherwise be ignored in silence.
  // Named at the caller's line (swarmagg.run or swarmagg.rates calls this one), so that each
  // call site warns, as Python's filters expect.
  if (ran.spec->run.trajectories > 0 || ran.spec->render.every > 0) {
    py::module_::import("warnings")
        .attr("warn")(
            "run() and rates() store no trajectories and draw no frames "
            "(run.trajectories, render.every): `swarmagg run` writes them, and a "
            "Simulation shows every step's state",
            py::none(), 2);
  }
  MeasuredRun result =
      call_interruptibly([&] { return run_world_measuring(*ran.spec, RunOptions{}, rates); });
  return RunOutput(ran, std::move(result));
}

}  // namespace

void bind_run(py::module_& module) {
  py::class_<RunOutput> output(module, "RunOutput", "The outputs of run(), as the CLI's texts.");
  // Nothing changes a run's outputs once made: a copy may be the same object.
  copied_as_itself(output);
  refuse_pickling(output,
                  "swarmagg.Run and swarmagg.Rates cannot be pickled: their results live in the "
                  "library's memory. Pickle what they return (frames and dicts), or the world "
                  "(run.world, which pickles) to run it again, with the same seed, elsewhere");
  output.def_property_readonly("world", &RunOutput::world)
      .def("timeseries_csv", &RunOutput::timeseries_csv_text)
      .def("summary_json", &RunOutput::summary_json)
      .def("partitions_csv", &RunOutput::partitions_csv_text)
      .def("model_csv", &RunOutput::model_csv_text)
      .def_property_readonly("measured", &RunOutput::measured)
      .def("rates_csv", &RunOutput::rates_csv_text)
      .def("rates_json", &RunOutput::rates_json_text);
  module.def("run", &run, py::arg("world"), py::arg("replicates") = py::none(),
             py::arg("seed") = py::none(), py::arg("threads") = py::none(),
             py::arg("engine") = py::none(), py::arg("rates") = false,
             "Runs the world's replicates (see swarmagg.run).");
}

}  // namespace swarmagg::python
