#include "reproduce/claims.hpp"

#include <cmath>
#include <cstdio>
#include <functional>

#include "reproduce/paper_predictions.hpp"

namespace swarmagg {
namespace {

std::string fixed(double value, int digits = 3) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

const FigureResult* with_world(const std::vector<FigureResult>& results, const std::string& world) {
  for (const FigureResult& r : results) {
    for (const std::string& name : r.figure.worlds) {
      if (name == world) return &r;
    }
  }
  return nullptr;
}

ClaimCheck unchecked(ClaimCheck claim, const std::string& missing) {
  claim.verdict = "not checked";
  claim.evidence = "world " + missing + " was not run";
  return claim;
}

// Supported when `winner` has the smaller error than `loser` in every listed world.
ClaimCheck compare_variants(ClaimCheck claim, const std::vector<FigureResult>& results,
                            const std::vector<std::string>& worlds, const std::string& winner,
                            const std::string& loser, const std::string& also = "") {
  int wins = 0;
  for (const std::string& world : worlds) {
    const FigureResult* r = with_world(results, world);
    const auto* errors = r ? model_errors(*r) : nullptr;
    if (!errors) return unchecked(claim, world);
    const double w = variant_error(*errors, winner), l = variant_error(*errors, loser);
    wins += w < l ? 1 : 0;
    claim.evidence += (claim.evidence.empty() ? "" : "; ") + world + ": " + winner + " " +
                      fixed(w) + " vs " + loser + " " + fixed(l);
    if (!also.empty())
      claim.evidence += " (" + also + " " + fixed(variant_error(*errors, also)) + ")";
  }
  claim.verdict = wins == static_cast<int>(worlds.size()) ? "supported" : "not supported";
  claim.evidence =
      std::to_string(wins) + "/" + std::to_string(worlds.size()) + " worlds: " + claim.evidence;
  return claim;
}

ClaimCheck overlap(ClaimCheck claim, const std::vector<FigureResult>& results,
                   const std::string& id) {
  for (const FigureResult& r : results) {
    if (r.figure.id != id || r.encounters.empty()) continue;
    double kinetic = 0.0, kinetic_max = 0.0, fit = 0.0;
    for (const EncounterPoint& p : r.encounters) {
      const double e = std::abs(p.simulated - p.kinetic) / p.kinetic;
      kinetic += e;
      kinetic_max = std::max(kinetic_max, e);
      fit += std::abs(p.simulated - p.paper_fit) / p.paper_fit;
    }
    const double n = static_cast<double>(r.encounters.size());
    claim.verdict = kinetic / n <= kOverlapTolerance ? "supported" : "not supported";
    claim.evidence = "mean |relative deviation| from kinetic theory " + fixed(100 * kinetic / n) +
                     " % (max " + fixed(100 * kinetic_max) + " %, tolerance " +
                     fixed(100 * kOverlapTolerance) + " %) over " +
                     std::to_string(r.encounters.size()) +
                     " worlds; from the paper's fitted formula " + fixed(100 * fit / n) + " %";
    return claim;
  }
  return unchecked(claim, id);
}

// Improved variant beats the original in more than half of all NOA and partition worlds.
ClaimCheck most_cases(ClaimCheck claim, const std::vector<FigureResult>& results) {
  int wins = 0, total = 0;
  for (const FigureResult& r : results) {
    if (r.noa) {
      wins +=
          variant_error(r.noa->errors, kPaperFitVariant) < variant_error(r.noa->errors, "original");
      ++total;
    } else if (r.partitions) {
      wins += variant_error(r.partitions->errors, "peripheral") <
              variant_error(r.partitions->errors, "original");
      ++total;
    }
  }
  if (total == 0) return unchecked(claim, "of Figs 9-29");
  claim.verdict = 2 * wins > total ? "supported" : "not supported";
  claim.evidence = "improved variant (collision-paper / peripheral) better in " +
                   std::to_string(wins) + "/" + std::to_string(total) + " experiments";
  return claim;
}

}  // namespace

std::vector<ClaimCheck> check_claims(const std::vector<FigureResult>& results) {
  const std::string fit = kPaperFitVariant;
  return {
      overlap({"Fig 7", "encounter frequency vs N overlaps collision theory", "", ""}, results,
              "fig07-collision-count"),
      overlap({"Fig 8", "encounter frequency vs v overlaps collision theory", "", ""}, results,
              "fig08-collision-speed"),
      compare_variants(
          {"Figs 9-11", "creation: Bayindir's original is more consistent than the improved model",
           "", ""},
          results, {"creation-50", "creation-100", "creation-150"}, "original", fit, "collision"),
      compare_variants({"Figs 12-13", "creation+growing: Bayindir's original fits better", "", ""},
                       results, {"creation-growing-80", "creation-growing-160"}, "original", fit,
                       "collision"),
      compare_variants(
          {"Figs 14-17", "creation+dissipation: the improved model fits better than the original",
           "", ""},
          results,
          {"creation-dissipation-0.0001", "creation-dissipation-0.0005",
           "creation-dissipation-0.001", "creation-dissipation-0.005"},
          fit, "original", "collision"),
      compare_variants(
          {"Fig 19", "full: the improved model is better at the larger p = 0.0025", "", ""},
          results, {"full-0.0025"}, fit, "original", "collision"),
      compare_variants(
          {"Fig 18", "full: Bayindir's original is better at the smaller p = 0.0005", "", ""},
          results, {"full-0.0005"}, "original", fit, "collision"),
      compare_variants(
          {"IV.B", "the improved model fits better for a large number of robots", "", ""}, results,
          {"creation-150", "creation-growing-160"}, fit, "original", "collision"),
      compare_variants(
          {"IV.B", "the improved model fits better for bigger leaving probabilities", "", ""},
          results, {"creation-dissipation-0.005", "full-0.0025"}, fit, "original", "collision"),
      compare_variants(
          {"VI", "for small N and small p Bayindir's original is better", "", ""}, results,
          {"creation-50", "creation-growing-80", "creation-dissipation-0.0001", "full-0.0005"},
          "original", fit, "collision"),
      compare_variants(
          {"Figs 20-25", "5 robots: the peripheral model is closer to the simulation", "", ""},
          results, {"soysal-5-constant", "soysal-5-inverse", "soysal-5-inverse_square"},
          "peripheral", "original"),
      compare_variants(
          {"Figs 26-29", "10 and 20 robots: the peripheral model is worse than the original", "",
           ""},
          results, {"soysal-10-constant", "soysal-20-constant"}, "original", "peripheral"),
      most_cases({"V", "the improved models fit better in most cases", "", ""}, results),
  };
}

}  // namespace swarmagg
