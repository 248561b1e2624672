#include "controllers/controller_registry.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>

#include "core/errors.hpp"

// Every controller, once: X(name) stands for name_registration(), defined in controllers/name/.
// Adding a controller adds one line above the last one.
// clang-format off
#define SWARMAGG_CONTROLLERS(X) \
  X(bayindir)                   \
  X(soysal)                     \
  X(collision)                  \
  X(cockroach)                  \
  /* end of the controllers */
// clang-format on

namespace swarmagg {

#define SWARMAGG_DECLARE_REGISTRATION(name) ControllerRegistration name##_registration();
SWARMAGG_CONTROLLERS(SWARMAGG_DECLARE_REGISTRATION)
#undef SWARMAGG_DECLARE_REGISTRATION

namespace {

std::vector<ControllerRegistration>& registrations() {
#define SWARMAGG_LIST_REGISTRATION(name) name##_registration(),
  static std::vector<ControllerRegistration> all = {
      SWARMAGG_CONTROLLERS(SWARMAGG_LIST_REGISTRATION)};
#undef SWARMAGG_LIST_REGISTRATION
  return all;
}

std::atomic<bool> catalog_built{false};

}  // namespace

const std::vector<ControllerRegistration>& controller_registrations() {
  return registrations();
}

void register_controller(ControllerRegistration registration) {
  if (catalog_built) {
    throw std::logic_error("controller '" + registration.world.type +
                           "' registered after the key table was built");
  }
  for (const ControllerRegistration& r : registrations()) {
    if (r.world.type == registration.world.type) {
      throw std::logic_error("controller '" + r.world.type + "' is registered twice");
    }
  }
  registrations().push_back(std::move(registration));
}

const std::vector<ControllerCatalogEntry>& controller_catalog() {
  static const std::vector<ControllerCatalogEntry> entries = [] {
    catalog_built = true;
    std::vector<ControllerCatalogEntry> world;
    for (const ControllerRegistration& r : controller_registrations()) world.push_back(r.world);
    return world;
  }();
  return entries;
}

// Each family of models reads these model.* keys (models/predictions.cpp and what it calls):
// the Bayindir equations and the encounter rate take kappa and the creation variant and have
// a stochastic version, the Soysal partition chain the leaving variant and its periphery; all
// read where they start (the encounter rate only in that `measured` needs a run's rates).
bool model_reads(const WorldSpec& spec, const std::string& path) {
  static const std::vector<std::string> bayindir = {
      "model.kappa", "model.creation", "model.stochastic_replicates", "model.initial_state"};
  static const std::vector<std::string> soysal = {"model.leaving", "model.periphery_cap",
                                                  "model.initial_state"};
  const auto holds = [&](const std::vector<std::string>& keys) {
    return std::find(keys.begin(), keys.end(), path) != keys.end();
  };
  switch (controller_rules(spec).model) {
    case ModelFamily::None:
      return false;
    case ModelFamily::Encounters:
    case ModelFamily::Bayindir:
      return holds(bayindir);
    case ModelFamily::Soysal:
      return holds(soysal);
  }
  return true;
}

bool controller_reads(const WorldSpec& spec, const WorldKey& key) {
  if (!key.path.starts_with("controller.") || key.path == "controller.type") return true;
  if (!key.controller.empty()) return key.controller == spec.controller.type;
  const std::vector<std::string>& shared = catalog_entry(spec.controller.type).shared_keys;
  return std::find(shared.begin(), shared.end(), key.path) != shared.end();
}

const ControllerRegistration& registration_of(const std::string& type) {
  for (const ControllerRegistration& r : controller_registrations()) {
    if (r.world.type == type) return r;
  }
  catalog_entry(type);  // throws, naming the registered types
  throw InputError("controller.type: no controller '" + type + "' is registered");
}

ControllerRules controller_rules(const WorldSpec& spec) {
  return registration_of(spec.controller.type).rules(spec);
}

std::unique_ptr<Controller> make_controller(const WorldSpec& spec) {
  return registration_of(spec.controller.type).make(spec);
}

const WorldKey& registered_key(const ControllerCatalogEntry& entry, const std::string& path) {
  for (const WorldKey& key : entry.keys) {
    if (key.path == path) return key;
  }
  throw InputError(entry.type + " registers no key " + path);
}

}  // namespace swarmagg
