#pragma once
// What `run --force` does to the run already in its folder: once the new simulation has
// finished (Ctrl-C before then leaves the earlier run whole), the earlier run's outputs go,
// so that none of them stays beside a run that writes no such file (its model.csv beside a
// `--no-model` run, whose plots would draw the old model; its rates beside a run without
// `--rates`). world.resolved.yaml goes first, so the folder reads incomplete meanwhile.
//
// Removed: the run's own files by name, its rates-<term> files for the terms its rates.csv
// lists, and its own folders plots/ and model-timeseries/ whole. Other files in the folder
// (yours) stay; trajectories.h5 and frames/ are their writers' to replace. A folder without
// world.resolved.yaml holds no complete run: of a folder `swarmagg rates` wrote (its rates.json
// records a world) the rates files go, nothing else.
#include <filesystem>
#include <string>
#include <vector>

#include "config/world_spec.hpp"

namespace swarmagg {

// Returns what could not be removed ("path: reason"), for the caller to warn about: the new
// run's outputs are written anyway.
std::vector<std::string> clear_earlier_run(const std::filesystem::path& out);

// Removes the rates-<term> files (.png, .gp, .csv) of the terms the rates.csv in `out` lists
// and of every term this version writes (kRateTerms), before a `rates` writes its own: a term
// it does not measure would keep an earlier plot.
void clear_earlier_rates(const std::filesystem::path& out, std::vector<std::string>& failures);

// `command` (model, rates) writes into `out`: refused (InputError, naming the keys that
// differ) unless `force` when `out` holds a run of another system (config/world_difference.hpp),
// whose plots would draw the new outputs as if they were its own, or rates `rates` measured in
// another system (their rates.json says which), which `rates` would replace and beside which
// `model` would write.
void refuse_another_worlds_outputs(const std::filesystem::path& out, const WorldSpec& spec,
                                   const std::string& command, bool force);

// Removes `path` (a folder whole); what could not be removed goes to `failures` as
// "path: reason". The removal every command's --force shares.
void remove_earlier_output(const std::filesystem::path& path, std::vector<std::string>& failures);

}  // namespace swarmagg
