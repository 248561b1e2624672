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
};

}  // namespace swarmagg
