// Rendering cost, drawing and PNG encoding measured apart (issue 4): 1,000 agents in an
// 800x800 frame, 30% of them waiting in aggregates of 5. Two densities: the paper's
// (150 agents on 180x180, so 1,000 on 465x465) and a crowded 180x180 arena, where every
// detection circle covers ~6x more pixels. Time is wall-clock (UseRealTime): llvmpipe draws
// on its own threads (LP_NUM_THREADS, default one per core), so the calling thread's CPU
// time under-counts; the counter process_cpu_ms is the CPU time of all threads per frame,
// the figure to compare when the machine is busy (wall time then mostly measures waiting).
//
//   build/bench/bench_render --benchmark_repetitions=5 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>
#include <time.h>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "config/world_spec.hpp"
#include "observers/swarm_snapshot.hpp"
#include "render/frame_layout.hpp"
#include "render/frame_recorder.hpp"
#include "render/frame_renderer.hpp"
#include "render/osmesa_context.hpp"
#include "render/png_writer.hpp"

namespace swarmagg {
namespace {

struct Scene {
  WorldSpec spec;
  std::vector<Vec2> positions;
  std::vector<AgentState> states;
  std::vector<std::int32_t> aggregate;
  int noa = 0;

  Scene(double side, int n) {
    spec.arena.width = side;
    spec.arena.height = side;
    spec.render.width = 800;
    spec.render.height = 800;
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0.0, side);
    const int grouped = n * 3 / 10 / 5 * 5;
    for (int a = 0; a < grouped / 5; ++a) {
      const double cx = u(rng);
      const double cy = u(rng);
      for (int m = 0; m < 5; ++m) {
        positions.push_back({cx + 2.0 * (m % 3), cy + 2.0 * (m / 3)});
        states.push_back(AgentState::Wait);
        aggregate.push_back(a);
      }
      ++noa;
    }
    const std::array<AgentState, 3> moving{AgentState::Go, AgentState::Leave, AgentState::Approach};
    for (int i = grouped; i < n; ++i) {
      positions.push_back({u(rng), u(rng)});
      states.push_back(moving[i % 3]);
      aggregate.push_back(-1);
    }
  }
  SwarmSnapshot snapshot() const { return {&spec, 1000, 100.0, positions, states, aggregate, noa}; }
};

double side_for(int density) {
  return density == 0 ? 465.0 : 180.0;
}

double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}

// Runs `body` once per iteration and reports the CPU time of all threads per iteration.
template <typename Body>
void measure(benchmark::State& state, Body body) {
  const double start = process_cpu_ms();
  for (auto _ : state) body();
  state.counters["process_cpu_ms"] =
      (process_cpu_ms() - start) / static_cast<double>(state.iterations());
}

void BM_Draw(benchmark::State& state) {
  const Scene scene(side_for(static_cast<int>(state.range(1))), static_cast<int>(state.range(0)));
  FrameRenderer renderer(800, 800);
  renderer.render(scene.snapshot());  // shader compilation
  measure(state, [&] { benchmark::DoNotOptimize(renderer.render(scene.snapshot()).data()); });
}
BENCHMARK(BM_Draw)
    ->ArgNames({"agents", "crowded"})
    ->Args({1000, 0})
    ->Args({1000, 1})
    ->Args({10000, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The naive baseline (~59 ms on an unloaded 2-core VM): every body a 32-segment triangle fan and
// every detection circle a 32-segment line loop, one draw call each, same context type. Run it
// beside BM_Draw on the same machine at the same time and compare the ratio.
void BM_DrawTriangleFansBaseline(benchmark::State& state) {
  const Scene scene(side_for(static_cast<int>(state.range(1))), static_cast<int>(state.range(0)));
  const FrameLayout layout = make_frame_layout(800, 800, scene.spec.arena);
  std::vector<std::uint8_t> pixels(800 * 800 * 4);
  OsMesaContext context(800, 800);
  context.bind(pixels);
  const char* vs =
      "#version 330 core\nlayout(location = 0) in vec2 p;\n"
      "void main() { gl_Position = vec4(p / 400.0 - 1.0, 0.0, 1.0); }\n";
  const char* fs = "#version 330 core\nuniform vec4 c;\nout vec4 o;\nvoid main() { o = c; }\n";
  const GLuint program = glCreateProgram();
  for (const auto& [kind, source] : {std::pair{GL_VERTEX_SHADER, vs}, {GL_FRAGMENT_SHADER, fs}}) {
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    glAttachShader(program, shader);
  }
  glLinkProgram(program);
  glUseProgram(program);
  const GLint colour = glGetUniformLocation(program, "c");
  constexpr int kSegments = 32;
  std::vector<float> vertices;  // per agent: fan (centre + 33 rim points), loop (32 points)
  const double r = scene.spec.robots.radius * layout.scale;
  const double s = scene.spec.robots.detection_radius * layout.scale;
  for (const Vec2 p : scene.positions) {
    const Vec2 c = layout.to_pixel(p);
    vertices.insert(vertices.end(), {static_cast<float>(c.x), static_cast<float>(c.y)});
    for (int k = 0; k <= kSegments; ++k) {
      const double a = 2 * M_PI * k / kSegments;
      vertices.push_back(static_cast<float>(c.x + r * std::cos(a)));
      vertices.push_back(static_cast<float>(c.y + r * std::sin(a)));
    }
    for (int k = 0; k < kSegments; ++k) {
      const double a = 2 * M_PI * k / kSegments;
      vertices.push_back(static_cast<float>(c.x + s * std::cos(a)));
      vertices.push_back(static_cast<float>(c.y + s * std::sin(a)));
    }
  }
  GLuint vao = 0;
  GLuint vbo = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  const auto draw = [&] {
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)),
                 vertices.data(), GL_STREAM_DRAW);
    const int per_agent = (kSegments + 2) + kSegments;
    for (std::size_t i = 0; i < scene.positions.size(); ++i) {
      const auto first = static_cast<GLint>(i * per_agent);
      glUniform4f(colour, 0.8f, 0.4f, 0.0f, 1.0f);
      glDrawArrays(GL_TRIANGLE_FAN, first, kSegments + 2);
      glUniform4f(colour, 0.5f, 0.5f, 0.5f, 1.0f);
      glDrawArrays(GL_LINE_LOOP, first + kSegments + 2, kSegments);
    }
    glFinish();
  };
  draw();
  measure(state, draw);
  glDeleteBuffers(1, &vbo);
  glDeleteVertexArrays(1, &vao);
  glDeleteProgram(program);
  context.release();
}
BENCHMARK(BM_DrawTriangleFansBaseline)
    ->ArgNames({"agents", "crowded"})
    ->Args({1000, 0})
    ->Args({1000, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_EncodePng(benchmark::State& state) {
  const Scene scene(side_for(static_cast<int>(state.range(1))), 1000);
  FrameRenderer renderer(800, 800);
  const auto frame = renderer.render(scene.snapshot());
  const std::vector<std::uint8_t> pixels(frame.begin(), frame.end());
  const auto path = std::filesystem::temp_directory_path() /
                    ("swarmagg-bench-" + std::to_string(::getpid()) + ".png");
  measure(state, [&] { write_png(path, 800, 800, pixels, static_cast<int>(state.range(0))); });
  state.counters["bytes"] = static_cast<double>(std::filesystem::file_size(path));
  std::filesystem::remove(path);
}
BENCHMARK(BM_EncodePng)
    ->ArgNames({"level", "crowded"})
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({1, 1})
    ->Args({6, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// What the simulation thread pays per recorded frame: record() alone, timed by hand, with
// 60 ms of (sleeping) simulation between frames so the encoder keeps up. It should cost the
// drawing plus a hand-over, not the PNG encoding.
void BM_RecordCallOnly(benchmark::State& state) {
  const Scene scene(side_for(0), 1000);
  const auto dir = std::filesystem::temp_directory_path() /
                   ("swarmagg-bench-frames-" + std::to_string(::getpid()));
  {
    FrameRecorder recorder(scene.spec, dir);
    recorder.record(scene.snapshot());  // shader compilation
    for (auto _ : state) {
      std::this_thread::sleep_for(std::chrono::milliseconds(60));
      const auto start = std::chrono::steady_clock::now();
      recorder.record(scene.snapshot());
      state.SetIterationTime(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
  }
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_RecordCallOnly)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(20);

// The same calls back to back: when frames come faster than one encoder writes them,
// record() waits for a free buffer (bounded memory), so this measures the encoder.
void BM_RecordBackToBack(benchmark::State& state) {
  const Scene scene(side_for(0), 1000);
  const auto dir = std::filesystem::temp_directory_path() /
                   ("swarmagg-bench-frames-" + std::to_string(::getpid()));
  {
    FrameRecorder recorder(scene.spec, dir);
    measure(state, [&] { recorder.record(scene.snapshot()); });
  }
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_RecordBackToBack)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace swarmagg
