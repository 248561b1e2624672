#pragma once
// The controllers swarmagg knows. A controller registers, in its own folder, one
// ControllerRegistration: its world-file entry (type name, own keys, sensing radius, checks),
// its factory and its rules; controller_registry.cpp lists each registration once. Adding a
// controller is its folder, its worlds and tests, and one line there (docs/controllers.md).
#include <memory>
#include <string>
#include <vector>

#include "config/controller_catalog.hpp"
#include "control_interface/controller_rules.hpp"
#include "controllers/controller.hpp"

namespace swarmagg {

struct ControllerRegistration {
  ControllerCatalogEntry world;
  std::unique_ptr<Controller> (*make)(const WorldSpec&) = nullptr;
  ControllerRules (*rules)(const WorldSpec&) = nullptr;
  // The per-step leave probability of a member of an aggregate of `size` agents that
  // perceives the other members (compare's escape-rate curves); nullptr when leaving does
  // not follow from the aggregate's size.
  double (*leave_probability_at_size)(const WorldSpec&, int size) = nullptr;
};

const std::vector<ControllerRegistration>& controller_registrations();
// Adds a controller this library does not list (a test suite's, a program's own). Call it
// before the first world is read: the key table is built once, from the controllers
// registered then. Throws std::logic_error when it comes later or the type is taken.
void register_controller(ControllerRegistration registration);
// The registration of `type`; throws InputError when none is registered under that name.
const ControllerRegistration& registration_of(const std::string& type);

// The rules of the world's controller (what it allows, which outputs and model apply).
ControllerRules controller_rules(const WorldSpec& spec);

// A world key of the world's controller, by path (e.g. "controller.stop_probability").
const WorldKey& registered_key(const ControllerCatalogEntry& entry, const std::string& path);

}  // namespace swarmagg
