#pragma once
// What compaction (docs/controllers.md) changes in one Bayindir or Soysal experiment, from the same
// figure reproduced twice: with compaction as the world says (the default, on) and with
// controller.compaction.enabled=false. Beside each model variant's error it keeps the
// simulated quantities that explain a change: how tightly members stand, how often searchers
// join aggregates against the model's capture radius, and how many LEAVE attempts get out.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "reproduce/figure_result.hpp"

namespace swarmagg {

// One quantity with compaction on and off; NaN where the run gives no value (no aggregate
// at the end, no growth or no LEAVE attempt).
struct OnOff {
  double on = 0.0;
  double off = 0.0;
};

struct CompactionEffect {
  std::string figures;  // the paper's figure numbers
  std::string world;
  bool bayindir = true;               // NOA RMSE; else Soysal, TV distance
  std::vector<std::string> variants;  // every variant compared, in the comparison's order
  std::vector<OnOff> errors;          // per variant
  OnOff final_noa;                    // Bayindir: mean over replicates at the last step
  OnOff member_spacing;   // final mean distance of a member to its nearest fellow member
  OnOff growth_vs_model;  // growths (joins) observed / expected from the model's capture radius
  OnOff escape_fraction;  // escapes / LEAVE attempts
  OnOff inside_attempt_share;  // LEAVE attempts from inside an aggregate / all attempts

  // The error of `variant` (NaN both ways when the comparison has no such variant).
  OnOff error(const std::string& variant) const;
};

// `on` and `off` are the same NOA or partition figure reproduced both ways.
CompactionEffect compaction_effect(const FigureResult& on, const FigureResult& off);

// Tidy: figure,world,compaction,quantity,value, one row per quantity and arm (quantity
// `error:<variant>`, final_noa, member_spacing, growth_vs_model, escape_fraction,
// inside_attempt_share); NaN
// values are left empty.
std::string compaction_csv(const std::vector<CompactionEffect>& effects);

}  // namespace swarmagg
