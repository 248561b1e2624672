#include "compare/engine_arm.hpp"

#include <memory>

namespace swarmagg {

ArmResult run_arm(const std::string& label, const WorldSpec& spec, int rim_below, bool progress) {
  ArmResult arm{label, spec, {}, {}};
  // One slot per replicate, sized before the threads start, so each observer writes only
  // its own slot and no lock is needed.
  arm.leave_attempts.resize(static_cast<std::size_t>(spec.run.replicates));
  RunOptions options;
  options.progress = progress;
  auto* slots = &arm.leave_attempts;
  options.observers = [slots, rim_below](int index) -> std::unique_ptr<ReplicateObserver> {
    return std::make_unique<LeaveAttemptObserver>(rim_below,
                                                  &(*slots)[static_cast<std::size_t>(index)]);
  };
  arm.run = run_world(arm.spec, options);
  return arm;
}

}  // namespace swarmagg
