#pragma once
// The probability q(i) that a LEAVE attempt from an aggregate of i agents comes back to it,
// predicted from the world's parameters alone (docs/models-returns.md derives it):
//  - the leaver starts on the rim of a packed disc, its centre R_agg(i) - r from the
//    aggregate's centre (R_agg(i) = r 1.20 i^0.48), and walks straight out (away from its
//    neighbours) for d = leave_timeout * v, ending D = R_agg(i) - r + d from the centre;
//  - it comes back as soon as it perceives a waiting member of what is left, an aggregate of
//    i - 1 whose members lie within R_agg(i - 1) - r of the centre: within the capture radius
//    rho = R_agg(i - 1) - r + c, c the approach radius for a controller that approaches
//    (Soysal), else the detection radius (Bayindir);
//  - D <= rho: it perceives the aggregate when its timeout ends, q = 1;
//  - else it searches on a uniformly random heading (the controller draws one at the
//    timeout) and keeps it: q = theta / pi, theta the half-angle of the headings that reach
//    the capture disc within the rest of the return window, v (window - leave_timeout):
//    theta = asin(rho / D) when that length reaches the tangent point, else the law of
//    cosines' angle at which a path of that length ends on the disc's edge.
// Only rim members get out (peripheral leaving emerges from the bodies); a leave law over the
// periphery (Soysal's peripheral variant, Bayindir's) discounts q(i), one over all members
// the q of every attempt (attempt_return_probability).
// A pair (i = 2) leaves no waiting member when the remaining agent resumes searching
// (isolated_wait: resume): q(2) = 0 then.
#include "config/world_spec.hpp"

namespace swarmagg {

// The model variant that knows returns (models/predictions.hpp).
inline constexpr const char* kReturnsVariant = "returns";

// The geometry alone: the probability that a searcher D from the centre of a capture disc of
// radius rho, on a uniformly random heading kept for `reach`, enters the disc (1 inside it).
double heading_capture_probability(double distance, double capture_radius, double reach);

// q(i) of a rim leaver of the world; 0 for a world whose agents never leave.
double return_probability(const WorldSpec& world, int size);

// q over every LEAVE attempt, rim or inside: an inside member that tries is enclosed by the
// bodies around it, still among its aggregate when its timeout ends, and comes back. With a
// rim share min(i, periph(i)) / i (models/aggregate_shape.hpp): share q(i) + (1 - share).
// This is what rates' `return` rows measure, and what a leave law over all members
// (model.leaving: original) must discount.
double attempt_return_probability(const WorldSpec& world, int size);

}  // namespace swarmagg
