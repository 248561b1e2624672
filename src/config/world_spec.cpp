#include "config/world_spec.hpp"

#include "config/controller_catalog.hpp"

namespace swarmagg {

double WorldSpec::sensing_radius() const {
  return catalog_entry(controller.type).sensing_radius(*this);
}

double WorldSpec::perception_radius() const {
  return catalog_entry(controller.type).perception_radius(*this);
}

}  // namespace swarmagg
