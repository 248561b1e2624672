#include "controllers/compaction.hpp"

namespace swarmagg {

CompactionRule compaction_rule(const WorldSpec& spec) {
  const CompactionSpec& compaction = spec.controller.compaction;
  return {compaction.enabled, spec.compaction_spacing(), compaction.gain, compaction.tolerance};
}

}  // namespace swarmagg
