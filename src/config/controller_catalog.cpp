#include "config/controller_catalog.hpp"

#include "core/errors.hpp"

namespace swarmagg {

const ControllerCatalogEntry& catalog_entry(const std::string& type) {
  std::string known;
  for (const ControllerCatalogEntry& entry : controller_catalog()) {
    if (entry.type == type) return entry;
    known += (known.empty() ? "" : ", ") + entry.type;
  }
  throw InputError("controller.type: no controller '" + type + "' is registered (" + known + ")");
}

}  // namespace swarmagg
