#pragma once
// `swarmagg compare`: one world run on the kinematic and on the Box2D engine with the same
// replicates and seeds (replicate k draws from the generator keyed by (run.seed, k) on
// either engine), compared, and written to one folder:
//   summary.txt, compare.json, noa.{csv,gp,png}, final_noa.csv, sizes.csv, final.{gp,png},
//   escape_rate.{csv,gp,png} (worlds with leaving), and each engine's ordinary run folder
//   in kinematic/ and box2d/.
#include <filesystem>
#include <string>
#include <vector>

#include "compare/arm_comparison.hpp"
#include "compare/engine_arm.hpp"

namespace swarmagg {

struct EngineComparison {
  ArmResult kinematic;
  ArmResult box2d;
  Comparison stats;  // a = kinematic, b = box2d
};

// The world on `engine` ("kinematic", "box2d"), through the key table and the world's and the
// engine's checks, as `--set engine.type=...` and the engine would check it: a world one arm
// cannot run is refused before either runs.
WorldSpec on_engine(const WorldSpec& spec, const std::string& engine);

// With `out`, the arms' rows are spooled to disk for write_compare_folder (run_arm).
EngineComparison compare_engines(const WorldSpec& spec, bool progress = false,
                                 const std::filesystem::path& out = {});

// Returns the plots that could not be drawn (write_comparison_plots), to warn about.
// `changes`: what the command line changed of the world file, for each arm's summary.json
// (each adds its engine.type, as `run --engine` does).
std::vector<std::string> write_compare_folder(const ArmResult& a, const ArmResult& b,
                                              const Comparison& c, const std::filesystem::path& out,
                                              const std::vector<std::string>& changes = {});

// What `compare --force` does to the comparison already in `out` once the new one is
// computed: the files above go, and the arms' folders whole (a comparison without leaving
// writes no escape_rate.*; an arm's trajectories.h5 put there by hand would stay beside a new
// arm). Other files stay. Returns what could not be removed ("path: reason"), to warn about.
std::vector<std::string> remove_earlier_comparison(const std::filesystem::path& out);

// runs/<world name>-compare unless --out says otherwise.
std::filesystem::path default_compare_folder(const WorldSpec& spec);

}  // namespace swarmagg
