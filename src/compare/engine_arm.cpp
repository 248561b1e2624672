#include "compare/engine_arm.hpp"

#include <memory>

#include "run/replicate.hpp"

namespace swarmagg {
namespace {

// Follows one replicate's aggregates after setup and every step; writes only its own slot,
// so replicates may run in any threads.
class LineageObserver final : public ReplicateObserver {
 public:
  explicit LineageObserver(LineageCounts& slot) : slot_(slot) {}
  void observe(const Replicate& replicate) override {
    lineage_.observe(replicate.aggregates().aggregate_of(), replicate.aggregates().count());
  }
  void finish() override { slot_ = lineage_.counts(); }

 private:
  AggregateLineage lineage_;
  LineageCounts& slot_;
};

}  // namespace

ArmResult run_arm(const std::string& label, const WorldSpec& spec, bool progress,
                  const std::filesystem::path& out) {
  ArmResult arm{label, spec, {}, {}, {}};
  arm.lineage.resize(static_cast<std::size_t>(spec.run.replicates));
  RunOptions options;
  options.progress = progress;
  if (!out.empty()) {
    arm.timeseries =
        std::make_unique<TimeseriesSpool>(out / label / "timeseries.csv", spec.run.replicates, out);
    options.timeseries = arm.timeseries.get();
  }
  options.observers = [&arm](int index) {
    return std::make_unique<LineageObserver>(arm.lineage[static_cast<std::size_t>(index)]);
  };
  arm.run = run_world(arm.spec, options);
  return arm;
}

}  // namespace swarmagg
