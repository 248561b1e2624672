#include "run/rate_collector.hpp"

#include <algorithm>

#include "controllers/controller_registry.hpp"
#include "observers/aggregate_geometry.hpp"
#include "rates/rate_recorder.hpp"
#include "run/recorded_steps.hpp"
#include "run/replicate.hpp"

namespace swarmagg {

namespace {

class RateObserver final : public ReplicateObserver {
 public:
  RateObserver(const WorldSpec& spec, std::optional<RateTally>& slot)
      : recorder_(spec.robots.count, spec.steps()),
        slot_(slot),
        collision_(controller_rules(spec).model == ModelFamily::Encounters),
        shape_rules_(ShapeRules::for_world(spec)) {}

  void observe(const Replicate& replicate) override {
    replicate_ = &replicate;  // alive until finish(): run_replicate owns it
    const auto sizes = replicate.aggregates().sizes();
    int free = replicate.spec().robots.count;
    if (!collision_) {
      for (const std::int32_t size : sizes) free -= size;
    }
    const EventCounts& events = replicate.events();
    recorder_.observe(replicate.steps_done(), free, sizes,
                      collision_ ? events.encounters : events.creations,
                      replicate.growths_by_size());
    const std::int64_t step = replicate.steps_done();
    if (!collision_ && step >= 1 && is_recorded_step(replicate.spec(), step))
      observe_shapes(replicate);
  }
  void finish() override {
    RateTally tally = recorder_.finish();
    if (replicate_) add_leave_episodes(replicate_->leave_episodes().tally(), tally);
    slot_ = std::move(tally);
  }

 private:
  static void add_leave_episodes(const LeaveTally& leave, RateTally& tally) {
    auto copy = [](const std::vector<std::int64_t>& from, std::vector<std::uint64_t>& to) {
      for (std::size_t m = 0; m < std::min(from.size(), to.size()); ++m)
        to[m] = static_cast<std::uint64_t>(from[m]);
    };
    copy(leave.attempts_by_size, tally.attempts);
    copy(leave.escapes_by_size, tally.escapes);
    copy(leave.aggregate_steps_by_size, tally.leave_aggregate_steps);
    copy(leave.return_attempts_by_size, tally.return_attempts);
    copy(leave.returns_by_size, tally.returns);
    copy(leave.return_steps_by_size, tally.return_steps);
    copy(leave.return_square_steps_by_size, tally.return_square_steps);
    copy(leave.returns_into_size, tally.returns_into);
    copy(leave.returning_aggregate_steps_by_size, tally.returning_searcher_steps);
  }

  // The aggregates' geometry (docs/models.md), measured as summary.json's final aggregates are, at
  // the recorded steps only (O(m^2) per aggregate).
  void observe_shapes(const Replicate& replicate) {
    members_.build(replicate.aggregates());
    for (const AggregateShape& shape :
         measure_aggregates(members_, replicate.engine().positions(), shape_rules_)) {
      recorder_.observe_shape(shape.size, shape.outer_radius, shape.rim);
    }
  }

  RateRecorder recorder_;
  const Replicate* replicate_ = nullptr;
  std::optional<RateTally>& slot_;
  bool collision_;
  ShapeRules shape_rules_;
  AggregateMembers members_;
};

}  // namespace

RateCollector::RateCollector(const WorldSpec& spec)
    : spec_(spec), tallies_(static_cast<std::size_t>(spec.run.replicates)) {}

std::unique_ptr<ReplicateObserver> RateCollector::observer(int index) {
  return std::make_unique<RateObserver>(spec_, tallies_.at(static_cast<std::size_t>(index)));
}

RateTally RateCollector::total() const {
  RateTally total(spec_.robots.count);
  for (const auto& tally : tallies_) {
    if (tally) total.merge(*tally);
  }
  return total;
}

}  // namespace swarmagg
