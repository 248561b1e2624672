#pragma once
// What the world file needs to know of each controller: its `controller.type` name, the keys
// only it reads, how far its sensors reach, and its cross-key checks. Each controller fills
// this in its own registration (controllers/controller_registry.cpp defines
// controller_catalog()), so the key table, `--set`, `validate`, did-you-mean, the writer and
// the fuzzers know every registered controller without naming one.
#include <optional>
#include <string>
#include <vector>

#include "config/world_keys.hpp"
#include "config/world_spec.hpp"

namespace swarmagg {

// A value that no single key makes wrong but the combination does.
struct KeyProblem {
  std::string key;
  std::string why;
};

struct ControllerCatalogEntry {
  std::string type;  // the controller.type value
  // Keys (controller.*) only this controller reads; written back only for its worlds.
  std::vector<WorldKey> keys;
  // The largest radius any of its sensors reads.
  double (*sensing_radius)(const WorldSpec&) = nullptr;
  // How far agents must perceive one another: 0 when it reads no neighbour lists, so an
  // engine need not build lists nobody reads.
  double (*perception_radius)(const WorldSpec&) = nullptr;
  std::optional<KeyProblem> (*check)(const WorldSpec&) = nullptr;
  // The shared controller.* keys of the key table (ControllerSpec's fields) it reads; the
  // resolved world writes only these and its own keys, so a world shows what acts on it.
  std::vector<std::string> shared_keys;
};

// Whether `spec`'s resolved world holds `key`: any key outside controller.*, controller.type,
// and the controller.* keys its controller reads.
bool controller_reads(const WorldSpec& spec, const WorldKey& key);
// Whether the macroscopic model of `spec`'s controller (its rules' model family) reads the
// model.* key `path` (false for every key when it has none). The resolved world writes every
// model key all the same: a sweep over controller types or `--set controller.type` on a
// resolved world gives the others' models what the file said.
bool model_reads(const WorldSpec& spec, const std::string& path);

// Every registered controller, in registration order (defined by the controllers library).
const std::vector<ControllerCatalogEntry>& controller_catalog();
// The entry of `type`; throws InputError naming the registered types when there is none.
const ControllerCatalogEntry& catalog_entry(const std::string& type);

}  // namespace swarmagg
