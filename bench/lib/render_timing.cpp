#include "bench/lib/render_timing.hpp"

#include <chrono>

#include "bench/lib/kinematic_bench.hpp"
#include "render/frame_renderer.hpp"
#include "run/replicate.hpp"

namespace swarmagg {

double render_ms_per_frame(int agents, int width, int height, int frames) {
  WorldSpec spec = bench_world(agents, BenchScenario::BayindirFull);
  Replicate replicate(spec, 0);
  for (int k = 0; k < 200; ++k) replicate.step();  // let aggregates form
  FrameRenderer renderer(width, height);
  renderer.render(replicate.snapshot());
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) renderer.render(replicate.snapshot());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return 1000.0 * seconds / frames;
}

}  // namespace swarmagg
