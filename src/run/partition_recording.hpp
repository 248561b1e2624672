#pragma once
// Whether a run records the partition of its swarm at every step (partitions.csv): Soysal
// worlds whose partitions the partition model can hold (at most 30 agents). A larger swarm
// enters a new partition almost every step, each written as one part per agent, so the
// record grew with the run's length times its agent count (gigabytes at 10^5 agents) while
// no model could use it.
#include "config/world_spec.hpp"

namespace swarmagg {

bool records_partitions(const WorldSpec& spec);

}  // namespace swarmagg
