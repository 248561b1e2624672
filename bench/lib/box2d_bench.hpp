#pragma once
// Throughput of the Box2D engine against a bare Box2D loop over the same bodies, for
// `swarmagg bench` and bench/box2d_bench. Method: N agents at the paper's density (150 per
// 180 x 180, the arena scaled with N), uniform non-overlapping positions, GO agents moving
// straight at v = 1 with random headings (they pass over each other, as GO agents do), dt
// 0.1, s = 4, r = 1. "Ours" is make_box2d_engine driven with MotionCommands (torus seam,
// sensor links, neighbour lists, encounters). "Bare" is one b2World with the same fixtures
// (disc r, sensor s/2, sensors meeting only sensors), the same world settings (no sleeping,
// no continuous collision), velocities set every step and nothing else: no torus, no
// listener, no neighbour lists. Both warm up for 10 steps (not timed, nor is building the
// world); then `repeats` timed runs of `steps` steps each, the two loops interleaved so they
// see the same machine load, and the best run of each is kept. A run is cut short so that
// bodies travel at most half the arena's side: the bare loop has no torus, so over longer
// runs its bodies spread out, meet less and step faster (at N = 100 the ratio read 1.29 for
// 3,000 steps and 1.45 for 30,000). Time is the calling thread's
// CPU time (a shared machine's descheduling is not counted). Read the ratio, not the
// absolute numbers.
#include <string>

namespace swarmagg {

struct Box2DBenchResult {
  int n = 0;
  int steps = 0;
  double body_steps_per_s = 0.0;             // ours
  double bare_box2d_body_steps_per_s = 0.0;  // bare Box2D
  double overhead() const { return bare_box2d_body_steps_per_s / body_steps_per_s; }
};

// `solid`: the agents also collide with each other (every body blocks every body), in both
// loops; the default is the GO agents' pass-over.
Box2DBenchResult bench_box2d(int n, int steps, int repeats = 3, bool solid = false);

}  // namespace swarmagg
