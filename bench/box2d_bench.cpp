// Box2D engine throughput against a bare Box2D loop over the same bodies, in the same run
// (issue 3: our overhead should stay within 1.5x). Method in
// bench/lib/box2d_bench.hpp; pin it to one core and read the ratio:
//
//   taskset -c 0 build/bench/bench_box2d [--solid] [N ...]     (default N: 100 1000 10000)
#include "bench/lib/box2d_bench.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

int main(int argc, char** argv) {
  bool solid = false;
  std::vector<int> sizes;
  for (int a = 1; a < argc; ++a) {
    if (std::strcmp(argv[a], "--solid") == 0) {
      solid = true;
    } else {
      sizes.push_back(std::atoi(argv[a]));
    }
  }
  if (sizes.empty()) sizes = {100, 1000, 10000};
  std::printf("Box2D engine vs bare Box2D, paper density, GO agents %s, best of 5\n",
              solid ? "colliding with each other" : "passing over each other");
  std::printf("%8s %8s %18s %18s %10s\n", "N", "steps", "ours body-steps/s", "bare body-steps/s",
              "bare/ours");
  for (const int n : sizes) {
    const int steps = std::max(30, 300000 / n);
    const swarmagg::Box2DBenchResult r = swarmagg::bench_box2d(n, steps, 5, solid);
    std::printf("%8d %8d %18.0f %18.0f %10.2f\n", r.n, r.steps, r.body_steps_per_s,
                r.bare_box2d_body_steps_per_s, r.overhead());
  }
  return 0;
}
