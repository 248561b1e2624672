#pragma once
// Helpers for the sweep tests: a fresh temporary folder per test, tiny worlds and sweep
// files written into it, and whole-file reads for byte comparisons.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace swarmagg::testing {

inline std::string read_file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_file_text(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// A world small enough that a run takes a few milliseconds: 10-20 agents, 1000 steps.
inline const char* kTinyWorld = R"(name: tiny
arena: {width: 60, height: 60}
robots: {count: 20}
controller: {type: bayindir, p_leave: 0.001}
run: {duration: 100, replicates: 5, seed: 3, record_every: 50}
)";

class SweepTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "swarmagg-sweep-XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    write_file_text(dir_ / "worlds" / "tiny.yaml", kTinyWorld);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Writes a sweep file beside a worlds/ folder holding tiny.yaml; returns its path.
  std::string sweep_file(const std::string& body, const std::string& name = "grid.yaml") const {
    write_file_text(dir_ / name, body);
    return (dir_ / name).string();
  }

  std::filesystem::path dir_;
};

// A 2 x 3 grid of tiny worlds, 2 replicates each: 12 runs.
inline const char* kGridSweep = R"(base: worlds/tiny.yaml
parameters:
  robots.count: [10, 20]
  controller.p_leave: [0.0005, 0.001, 0.005]
replicates: 2
seed: 7
)";

}  // namespace swarmagg::testing
