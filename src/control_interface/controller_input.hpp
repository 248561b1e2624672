#pragma once
// Everything a controller reads for one decision: what each agent's sensors give (neighbours
// within the sensing radius, wall bumpers) and the aggregate facts. No engine type appears.
#include <cstdint>
#include <span>

#include "control_interface/aggregate_facts.hpp"
#include "control_interface/neighbour_lists.hpp"
#include "control_interface/wall_contacts.hpp"

namespace swarmagg {

struct ControllerInput {
  std::int64_t step = 0;
  const NeighbourLists& neighbours;
  std::span<const std::uint8_t> reflections;  // Reflection bits (wall_contacts.hpp)
  AggregateFacts aggregates;                  // of the states the decision starts from
  // Cumulative growths by the size of the aggregate joined ([m]; a searcher that joins a
  // pair formed in the same decision counts at m = 2), counted when not empty
  // (count_growth_by_size). Observers (measured rates) read them; no decision depends on them.
  std::span<std::uint64_t> growths_by_size = {};
};

}  // namespace swarmagg
