#pragma once
// Where the models start (docs/models.md, model.initial_state). Random placement lets agents start
// within s of each other; the first decision pairs them at once, before any encounter. The
// models therefore start from the state after the first decision (step 1), not from all
// agents searching (the paper's start, kept as `all_searching`).
//
// `placement` (the default) is the mean state after the first decision over placements drawn
// as runs draw them (PlacementSample, made by run/placement_sample.hpp: the models do not
// place agents themselves). It holds at any density and for given positions.
//
// `placement_second_order` is the expectation derived to second order in q, the probability
// that a given pair starts within s. Placement draws
// positions uniformly and rejects body overlaps (distance < 2r), so at low density a pair is
// uniform outside 2r: q = pi (s^2 - (2r)^2) / A. Let j, k be two agents within s of a third,
// i (uniform in the annulus 2r..s around it); o = P(|j - k| < 2r) (they would overlap, so
// such cherries are rejected) and t = P(2r <= |j - k| <= s) (a triangle). With C2 = N(N-1)/2
// and C3 = N(N-1)(N-2)/6, the expected numbers of close pairs (edges), of two edges sharing
// an agent (cherries) and of triangles are
//   E = C2 q,   K = 3 C3 q^2 (1 - o),   T = C3 q^2 t,
// and components of four or more agents are O(q^3). Greedy pairing matches one pair in every
// component of two or three agents, so the pairs formed are E - K + T (to first order E, the
// issue's N(N-1)/2 pi s^2 / A before the body exclusion). With joining allowed the third
// agent of a three-agent component joins its pair: n_3 = K - 2T aggregates of three and
// n_2 = E - 2K + 3T of two; under join: false the third agent stays searching. The expansion
// leaves out that a cherry must also be apart from every other agent (a factor of about
// exp(-3 (N-1) q)) and every larger component: with (N-1) q = 0.16 (60 agents on 120 x 120)
// the pairs match the runs' but the triples come out 28 % high, and from (N-1) q of about 0.3
// the counts are wrong altogether (docs/models.md).
#include <map>
#include <vector>

#include "config/world_spec.hpp"
#include "models/measured_terms.hpp"
#include "models/partitions.hpp"

namespace swarmagg {

// q: the probability that two given agents of a random placement start within s.
double placement_pair_probability(const WorldSpec& world);

// P(|j - k| <= distance) for j, k independent and uniform in the annulus inner..outer
// around a common centre (numerical quadrature over the two radii).
double annulus_distance_probability(double inner, double outer, double distance);

struct FirstDecision {
  double pairs = 0.0;    // expected aggregates of two
  double triples = 0.0;  // expected aggregates of three (joining allowed)
};

// The expectation above, for a random placement of an aggregating world.
FirstDecision expected_first_decision(const WorldSpec& world);

// The mean aggregates after the first decision of sampled placements.
struct PlacementSample {
  std::vector<double> aggregates;   // [m], m = 0..N: mean aggregates of size m
  int placements = 0;               // placements drawn
  double noa_standard_error = 0.0;  // of the mean number of aggregates
  // The fraction of placements whose first decision left each partition of N (parts
  // decreasing, free agents as parts of 1), for swarms of at most kSampledPartitionsUpTo
  // agents: the partition model starts from it exactly.
  std::map<Partition, double> partitions;
};
inline constexpr int kSampledPartitionsUpTo = 30;

// Whether the world's models start from a PlacementSample: `placement`, for a controller that
// forms aggregates.
bool starts_from_placement_sample(const WorldSpec& world);

// The aggregates ([m], m = 0..N; indices 0 and 1 zero) the models hold after the first
// decision, by world.model.initial_state, or none (an empty vector) for all_searching and
// for collision-controller worlds (they form no aggregates). `sample` must be given when
// starts_from_placement_sample(world) (std::logic_error otherwise: a caller's mistake);
// `measured` must hold the initial state when the key says `measured` (InputError
// otherwise). placement_second_order, an expectation over random placements, starts given
// positions from all searching.
std::vector<double> start_aggregates(const WorldSpec& world, const MeasuredTerms* measured,
                                     const PlacementSample* sample);

// The sample's partitions where the world starts from the sample (`placement`), else none.
const std::map<Partition, double>* start_partitions(const WorldSpec& world,
                                                    const PlacementSample* sample);

}  // namespace swarmagg
