#pragma once
// The statistics of a comparison of two arms (compare/engine_arm.hpp): the difference in
// mean final NOA with its Welch interval, KS tests on the final NOA and on the pooled final
// aggregate sizes, the encounter rates, and the LEAVE episodes pooled over the replicates
// (attempts and escapes split by rim and inside, the rim rule of docs/models.md, and by aggregate
// size), and where the aggregates came from: births, deaths, and the merges and splits the
// models leave out (observers/aggregate_lineage.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "compare/engine_arm.hpp"
#include "compare/ks_test.hpp"
#include "compare/proportion_test.hpp"
#include "compare/welch_interval.hpp"
#include "observers/leave_tally.hpp"

namespace swarmagg {

constexpr double kSignificance = 0.05;  // two-sided, per test; 95% intervals

struct ArmSummary {
  std::string label;
  std::vector<double> final_noa;        // per replicate
  std::vector<double> final_sizes;      // every final aggregate of every replicate
  std::vector<double> encounter_rates;  // per replicate, encounters per tu
  MeanInterval noa;
  MeanInterval encounter_rate;
  LeaveTally leave;                      // pooled over the replicates
  std::vector<ReplicateTrials> escapes;  // per replicate: escapes of its LEAVE attempts
  std::vector<LineageCounts> lineage;    // per replicate, the whole run
  std::vector<double> net_merge_rates;   // per replicate, (merges - splits) per tu
  MeanInterval net_merge_rate;
};

struct Comparison {
  ArmSummary a;
  ArmSummary b;
  WelchResult noa_difference;  // b - a
  KsResult ks_noa;
  KsResult ks_sizes;
  WelchResult encounter_rate_difference;  // b - a, per-replicate encounters per tu
  ProportionResult escape_fraction;       // LEAVE attempts that got out (proportion_test.hpp)
  WelchResult net_merge_rate_difference;  // b - a, per-replicate net merges per tu
  bool has_leaving = false;
  // One verdict per quantity, each significant at kSignificance: the final NOA (Welch on the
  // mean, KS on the final NOA and on the final aggregate sizes), the encounter rate (Welch),
  // the escape fraction (Welch on the replicates' variance; only when agents leave) and the net
  // merge rate
  // (Welch).
  // The KS test on the final sizes needs aggregates in both arms, the escape fraction LEAVE
  // attempts in both (0 of 0 is no fraction): otherwise "not judged", not "no difference".
  bool sizes_judged() const;
  bool escape_fraction_judged() const;
  bool noa_differs() const;
  bool encounter_rate_differs() const;
  bool escape_fraction_differs() const;
  bool net_merge_rate_differs() const;
  // Any of the four, with no correction for testing four quantities: arms that are the same
  // world differ in one of them more often than kSignificance says (docs/outputs-and-progress.md).
  bool differs() const;
};

ArmSummary summarize_arm(const ArmResult& arm);
Comparison compare_arms(const ArmResult& a, const ArmResult& b);
// Whether agents of this world leave aggregates at all.
bool world_has_leaving(const WorldSpec& spec);

}  // namespace swarmagg
