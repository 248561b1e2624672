#include "models/initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"

namespace swarmagg {

namespace {

// Midpoint rule over both radii; the angle between j and k is uniform, so for given radii
// the probability that they lie within `distance` is the closed form theta / pi. 400 x 400
// points put the error near 1e-5, far below the second-order terms it feeds.
constexpr int kRadiusPoints = 400;

double placement_area(const WorldSpec& world) {
  const double margin = world.arena.topology == Topology::Walls ? world.robots.radius : 0.0;
  return (world.arena.width - 2.0 * margin) * (world.arena.height - 2.0 * margin);
}

}  // namespace

double annulus_distance_probability(double inner, double outer, double distance) {
  if (outer <= inner) return 0.0;
  const double width = (outer - inner) / kRadiusPoints;
  const double norm = outer * outer - inner * inner;
  double total = 0.0;
  for (int a = 0; a < kRadiusPoints; ++a) {
    const double r1 = inner + (a + 0.5) * width;
    for (int b = 0; b < kRadiusPoints; ++b) {
      const double r2 = inner + (b + 0.5) * width;
      const double cosine = (r1 * r1 + r2 * r2 - distance * distance) / (2.0 * r1 * r2);
      const double angle = std::acos(std::clamp(cosine, -1.0, 1.0));
      total += (2.0 * r1 * width / norm) * (2.0 * r2 * width / norm) * angle / std::numbers::pi;
    }
  }
  return total;
}

double placement_pair_probability(const WorldSpec& world) {
  const double s = world.robots.detection_radius;
  const double contact = 2.0 * world.robots.radius;
  if (s <= contact) return 0.0;
  return std::numbers::pi * (s * s - contact * contact) / placement_area(world);
}

FirstDecision expected_first_decision(const WorldSpec& world) {
  const double n = world.robots.count;
  const double q = placement_pair_probability(world);
  if (q <= 0.0 || n < 2) return {};
  const double contact = 2.0 * world.robots.radius;
  const double s = world.robots.detection_radius;
  const double overlap = annulus_distance_probability(contact, s, contact);
  const double triangle = annulus_distance_probability(contact, s, s) - overlap;
  const double pairs_c2 = n * (n - 1.0) / 2.0;
  const double triples_c3 = n * (n - 1.0) * (n - 2.0) / 6.0;
  const double edges = pairs_c2 * q;
  const double cherries = 3.0 * triples_c3 * q * q * (1.0 - overlap);
  const double triangles = triples_c3 * q * q * triangle;
  FirstDecision first;
  if (world.controller.join) {
    first.triples = std::max(0.0, cherries - 2.0 * triangles);
    first.pairs = std::max(0.0, edges - 2.0 * cherries + 3.0 * triangles);
  } else {
    first.pairs = std::max(0.0, edges - cherries + triangles);
  }
  // Beyond the expansion's range (dense placements) the counts cannot use more agents than
  // there are.
  const double used = 2.0 * first.pairs + 3.0 * first.triples;
  if (used > n) {
    first.pairs *= n / used;
    first.triples *= n / used;
  }
  return first;
}

bool starts_from_placement_sample(const WorldSpec& world) {
  const ModelFamily model = controller_rules(world).model;
  return world.model.initial_state == InitialState::Placement &&
         (model == ModelFamily::Bayindir || model == ModelFamily::Soysal);
}

std::vector<double> start_aggregates(const WorldSpec& world, const MeasuredTerms* measured,
                                     const PlacementSample* sample) {
  const int n = world.robots.count;
  const bool aggregating = controller_rules(world).model != ModelFamily::Encounters;
  switch (world.model.initial_state) {
    case InitialState::AllSearching:
      return {};
    case InitialState::Placement: {
      if (!aggregating) return {};
      if (!sample) throw std::logic_error("model.initial_state: placement needs a sample");
      return sample->aggregates;
    }
    case InitialState::PlacementSecondOrder: {
      if (!aggregating || !world.robots.random_placement()) return {};
      const FirstDecision first = expected_first_decision(world);
      std::vector<double> start(static_cast<std::size_t>(n) + 1, 0.0);
      if (n >= 2) start[2] = first.pairs;
      if (n >= 3) start[3] = first.triples;
      return start;
    }
    case InitialState::Measured: {
      if (!measured || measured->initial.empty()) {
        throw InputError(
            "model.initial_state: measured needs the state a run measured after its first "
            "decision: give `model --rates rates.csv` (from `swarmagg rates` or `run --rates`), "
            "or use placement or all_searching");
      }
      if (!aggregating) return {};
      std::vector<double> start(static_cast<std::size_t>(n) + 1, 0.0);
      for (const auto& [size, count] : measured->initial) {
        if (size >= 2 && size <= n) start[static_cast<std::size_t>(size)] = count;
      }
      return start;
    }
  }
  return {};
}

const std::map<Partition, double>* start_partitions(const WorldSpec& world,
                                                    const PlacementSample* sample) {
  if (!sample || world.model.initial_state != InitialState::Placement) return nullptr;
  return &sample->partitions;
}

}  // namespace swarmagg
