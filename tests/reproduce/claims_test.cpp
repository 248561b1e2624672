#include "reproduce/claims.hpp"

#include <gtest/gtest.h>

namespace swarmagg {
namespace {

FigureResult soysal_world(const std::string& name, double original, double peripheral,
                          double floor) {
  FigureResult r;
  r.figure = {.id = name, .figures = "20-25", .title = name, .worlds = {name}};
  PartitionComparison c;
  c.errors = {{"original", original, floor}, {"peripheral", peripheral, floor}};
  r.partitions = c;
  return r;
}

ClaimCheck claim(const std::vector<ClaimCheck>& claims, const std::string& figures) {
  for (const ClaimCheck& c : claims) {
    if (c.figures == figures) return c;
  }
  throw std::runtime_error("no claim " + figures);
}

// Two variants whose errors differ by less than their noise floor are not told apart: a claim
// resting on such comparisons is undecided, not refuted or supported by a coin's toss.
TEST(Claims, DifferencesWithinTheNoiseFloorDecideNothing) {
  const std::vector<FigureResult> close{soysal_world("soysal-5-constant", 0.628, 0.631, 0.1),
                                        soysal_world("soysal-5-inverse", 0.0964, 0.0953, 0.1),
                                        soysal_world("soysal-5-inverse_square", 0.036, 0.041, 0.1)};
  const ClaimCheck undecided = claim(check_claims(close), "Figs 20-25");
  EXPECT_EQ(undecided.verdict, "undecided");
  EXPECT_NE(undecided.evidence.find("0/3 worlds, 3 within the noise floor"), std::string::npos)
      << undecided.evidence;
  // One world where the original is closer by more than the floor refutes the claim.
  std::vector<FigureResult> refuted = close;
  refuted[2] = soysal_world("soysal-5-inverse_square", 0.036, 0.5, 0.1);
  EXPECT_EQ(claim(check_claims(refuted), "Figs 20-25").verdict, "not supported");
  // Closer beyond the floor in every world supports it.
  std::vector<FigureResult> supported;
  for (const FigureResult& r : close)
    supported.push_back(soysal_world(r.figure.worlds.front(), 0.6, 0.2, 0.1));
  EXPECT_EQ(claim(check_claims(supported), "Figs 20-25").verdict, "supported");
}

// --only can run part of a claim's worlds: Fig 7 over 1 of its 11 worlds, or V over one
// experiment, read as the paper's verdicts. They are not checked.
TEST(Claims, AClaimOverPartOfItsWorldsIsNotChecked) {
  FigureResult fig7;
  fig7.figure = {.id = "fig07-collision-count",
                 .figures = "7",
                 .title = "Fig 7",
                 .kind = FigureKind::EncountersVsCount,
                 .worlds = {"collision-count-100"}};
  fig7.encounters = {
      {.agents = 100, .speed = 1, .simulated = 0.19, .kinetic = 0.17, .paper_fit = 0.49}};
  const std::vector<FigureResult> partial{fig7, soysal_world("soysal-5-constant", 0.6, 0.1, 0.01)};
  const std::vector<ClaimCheck> claims = check_claims(partial);
  for (const char* figures : {"Fig 7", "V"}) {
    const ClaimCheck c = claim(claims, figures);
    EXPECT_EQ(c.verdict, "not checked") << figures << ": " << c.evidence;
    EXPECT_NE(c.evidence.find("of its"), std::string::npos) << c.evidence;
  }
}

}  // namespace
}  // namespace swarmagg
