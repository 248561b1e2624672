#include "run/partition_recording.hpp"

#include "controllers/controller_registry.hpp"
#include "models/partitions.hpp"
#include "models/soysal_model.hpp"

namespace swarmagg {

bool records_partitions(const WorldSpec& spec) {
  return controller_rules(spec).records_partitions &&
         partition_count(spec.robots.count) <= kLargestPartitionChain;
}

}  // namespace swarmagg
