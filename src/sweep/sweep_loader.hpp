#pragma once
// Reads a sweep file (YAML):
//
//   name: p-leave-vs-count          # optional; default: the file name without .yaml
//   base: ../../worlds/examples/demo.yaml   # relative to the sweep file
//   parameters:                     # world key paths -> non-empty lists of values
//     robots.count: [30, 60]
//     controller.p_leave: [0.0005, 0.001, 0.005]
//   replicates: 3                   # per point; default: the base world's run.replicates
//   seed: 7                         # default: the base world's run.seed
//
// The key paths are those of docs/reference/world-keys.md. Every value is checked up front
// against its world key; any problem is an InputError naming the sweep file, line, column
// and key. name, run.seed, run.replicates and render.*
// cannot be swept: the sweep sets them itself.
#include <string>

#include "sweep/sweep_plan.hpp"

namespace swarmagg {

SweepPlan load_sweep(const std::string& path);

}  // namespace swarmagg
