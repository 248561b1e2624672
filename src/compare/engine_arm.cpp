#include "compare/engine_arm.hpp"

namespace swarmagg {

ArmResult run_arm(const std::string& label, const WorldSpec& spec, bool progress) {
  ArmResult arm{label, spec, {}};
  RunOptions options;
  options.progress = progress;
  arm.run = run_world(arm.spec, options);
  return arm;
}

}  // namespace swarmagg
