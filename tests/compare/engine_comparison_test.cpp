#include "compare/engine_comparison.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis/csv_reader.hpp"
#include "compare/compare_plots.hpp"
#include "config/world_loader.hpp"
#include "core/errors.hpp"
#include "core/time_text.hpp"
#include "plot/drawn_points.hpp"
#include "plot/gnuplot.hpp"
#include "run/run_folder.hpp"
#include "testing/scratch_dir.hpp"

namespace swarmagg {
namespace {

WorldSpec tiny_world() {
  return load_world_text(R"(
name: tiny
arena: {width: 40, height: 40}
robots: {count: 16}
controller: {type: bayindir, p_leave: 0.005, leave_timeout: 5}
run: {duration: 60, replicates: 3, record_every: 20, seed: 5}
)",
                         "tiny");
}

// A world Box2D cannot run faithfully (here a speed needing more than its substeps) is refused
// before the kinematic arm runs, not after it (a long comparison lost its first arm).
TEST(EngineComparison, AWorldBox2dCannotRunIsRefusedBeforeEitherArm) {
  WorldSpec fast = tiny_world();
  fast.robots.speed = 150.0;
  fast.robots.radius = 0.01;
  fast.robots.detection_radius = 0.04;
  fast.engine.dt = 0.2;
  fast.arena.width = fast.arena.height = 200.0;
  EXPECT_NO_THROW(on_engine(fast, "kinematic"));
  EXPECT_THAT([&] { on_engine(fast, "box2d"); },
              ::testing::ThrowsMessage<InputError>(
                  ::testing::HasSubstr("would need more than 4096 Box2D substeps")));
}

TEST(EngineComparison, RunsBothEnginesWithTheSameSeeds) {
  const EngineComparison result = compare_engines(tiny_world());
  EXPECT_EQ(result.kinematic.spec.engine.type, EngineType::Kinematic);
  EXPECT_EQ(result.box2d.spec.engine.type, EngineType::Box2D);
  ASSERT_EQ(result.box2d.run.replicates.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(result.kinematic.run.replicates[k].seed, result.box2d.run.replicates[k].seed);
  }
  EXPECT_EQ(result.stats.a.label, "kinematic");
  EXPECT_EQ(result.stats.b.label, "box2d");
}

// A setting only the kinematic engine offers is refused before either arm runs, not after
// the kinematic one (whose folder would then hold a world Box2D cannot load back).
TEST(EngineComparison, RefusesAWorldTheBox2dEngineCannotRunBeforeRunning) {
  WorldSpec world = tiny_world();
  world.engine.contact = ContactResponse::Stop;
  EXPECT_THAT([&] { compare_engines(world); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("engine.contact")));
}

// A comparison ending with no aggregate in any replicate (two agents far apart, 1 tu) is a
// result like any other: every plot drawn, the sizes panel saying why it is empty, no escape
// rate plot for a table without rows. gnuplot used to fail on the empty table ("x range is
// invalid") and `compare` with it.
TEST(EngineComparison, NoAggregateAtTheEndStillDrawsEveryPlot) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot not installed";
  WorldSpec world = tiny_world();
  world.robots.count = 2;
  world.run.duration = 1.0;
  world.run.record_every = 1;
  const EngineComparison result = compare_engines(world);
  ASSERT_TRUE(result.stats.a.final_sizes.empty() && result.stats.b.final_sizes.empty());
  const testing::ScratchDir scratch("compare-test");
  EXPECT_THAT(write_compare_folder(result.kinematic, result.box2d, result.stats, scratch.path()),
              ::testing::IsEmpty());
  EXPECT_TRUE(std::filesystem::exists(scratch.path() / "final.png"));
  EXPECT_TRUE(std::filesystem::exists(scratch.path() / "escape_rate.csv"));
  EXPECT_FALSE(std::filesystem::exists(scratch.path() / "escape_rate.png"));
}

TEST(EngineComparison, WritesTheFolder) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot not installed";
  const EngineComparison result = compare_engines(tiny_world());
  const testing::ScratchDir scratch("compare-test");
  const auto& out = scratch.path();
  write_compare_folder(result.kinematic, result.box2d, result.stats, out);
  for (const char* name :
       {"summary.txt", "compare.json", "noa.csv", "noa.gp", "noa.png", "final_noa.csv", "sizes.csv",
        "final.gp", "final.png", "escape_rate.csv", "escape_rate.gp", "escape_rate.png",
        "kinematic/timeseries.csv", "box2d/timeseries.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
  }
}

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> files_in(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    names.push_back(std::filesystem::relative(entry.path(), folder).string());
  std::sort(names.begin(), names.end());
  return names;
}

// A comparison given its folder spools the arms' rows to disk (none held in memory) and
// writes the same files as one that held them.
TEST(EngineComparison, SpooledRowsGiveTheSameFolder) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot not installed";
  const testing::ScratchDir scratch("compare-test");
  const EngineComparison held = compare_engines(tiny_world());
  write_compare_folder(held.kinematic, held.box2d, held.stats, scratch.path() / "held");
  const std::filesystem::path spooled = scratch.path() / "spooled";
  const EngineComparison result = compare_engines(tiny_world(), false, spooled);
  for (const ArmResult* arm : {&result.kinematic, &result.box2d}) {
    for (const ReplicateOutcome& r : arm->run.replicates) EXPECT_TRUE(r.rows.empty());
  }
  write_compare_folder(result.kinematic, result.box2d, result.stats, spooled);
  const std::vector<std::string> names = files_in(scratch.path() / "held");
  EXPECT_EQ(files_in(spooled), names);
  for (const char* name : {"noa.csv", "kinematic/timeseries.csv", "box2d/timeseries.csv",
                           "final_noa.csv", "sizes.csv", "compare.json"}) {
    EXPECT_TRUE(file_text(spooled / name) == file_text(scratch.path() / "held" / name)) << name;
  }
}

// Interrupted or failed before its folder is written, a comparison leaves none of its rows.
TEST(EngineComparison, AComparisonNeverWrittenLeavesNoRows) {
  const testing::ScratchDir scratch("compare-test");
  { const EngineComparison result = compare_engines(tiny_world(), false, scratch.path()); }
  EXPECT_THAT(files_in(scratch.path()), ::testing::IsEmpty());
}

// noa.csv's time is the one the replicates knew (step * dt), printed as their timeseries.csv
// prints it, whatever dt: at dt = 0.0125, step 8003 is 100.0375 (six digits made it 100.038,
// and read back from its CSV text and printed again 100.037).
TEST(ComparePlots, TheNoaBandTimeIsTheReplicatesTime) {
  const testing::ScratchDir scratch("compare-test");
  WorldSpec world = tiny_world();
  world.engine.dt = 0.0125;
  world.run.duration = 101.0;  // 8,081 recorded steps, none thinned
  world.run.record_every = 1;
  world.run.replicates = 2;
  const EngineComparison result = compare_engines(world, false, scratch.path());
  for (const ArmResult* arm : {&result.kinematic, &result.box2d})
    write_run_folder(arm->spec, arm->run, scratch.path() / arm->label, {}, arm->timeseries.get());
  std::istringstream csv(noa_band_csv(result.kinematic, result.box2d, scratch.path()));
  std::string line;
  std::getline(csv, line);  // the header
  CsvReader replicates(scratch.path() / "kinematic" / "timeseries.csv");
  const std::size_t replicate = replicates.column("replicate"), time = replicates.column("time");
  int rows = 0;
  while (replicates.next() && replicates.cell(replicate) == "0") {
    ASSERT_TRUE(std::getline(csv, line));
    ASSERT_EQ(line.substr(0, line.find(',')), replicates.cell(time)) << "row " << rows;
    EXPECT_EQ(replicates.cell(time), time_text(rows * world.engine.dt));
    ++rows;
  }
  EXPECT_EQ(rows, 8081);
  EXPECT_FALSE(std::getline(csv, line));
}

// A long comparison's noa.csv holds the points its plot draws, not every recorded step.
TEST(ComparePlots, TheNoaBandOfALongComparisonIsThinned) {
  const testing::ScratchDir scratch("compare-test");
  WorldSpec world = tiny_world();
  world.run.duration = 2000.0;  // 20,001 recorded steps at dt 0.1
  world.run.record_every = 1;
  world.run.replicates = 2;
  const EngineComparison result = compare_engines(world, false, scratch.path());
  for (const ArmResult* arm : {&result.kinematic, &result.box2d})
    write_run_folder(arm->spec, arm->run, scratch.path() / arm->label, {}, arm->timeseries.get());
  const std::string csv = noa_band_csv(result.kinematic, result.box2d, scratch.path());
  const auto lines = static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n'));
  EXPECT_EQ(lines, 1 + drawn_indices(20001).size());  // the header and the points drawn
  EXPECT_LE(lines, 1 + kMostDrawnPoints);
  EXPECT_THAT(csv.substr(csv.rfind('\n', csv.size() - 2) + 1), ::testing::StartsWith("2000,"));
}

TEST(ComparePlots, HistogramCountsEachValueOfEachArm) {
  EXPECT_EQ(histogram_csv("size", "a", {2, 2, 3}, "b", {3, 5}), "size,a,b\n2,2,0\n3,1,1\n5,0,1\n");
}

// Hand-made tallies: size 2 seen by both arms, size 10 by the second only. Laws with
// p = 0.001 per step, dt = 0.1: m p/dt = 0.02 and 0.1; periph(2) is capped at 2, periph(10)
// = pi (1.2 10^0.48 - 1) = 8.24.
TEST(ComparePlots, EscapeRateIsEscapesPerAggregateTimeBesideBothLaws) {
  WorldSpec spec = tiny_world();
  spec.controller.p_leave = 0.001;
  const ArmResult a{"a", spec, {}, {}, {}};
  const ArmResult b{"b", spec, {}, {}, {}};
  Comparison c;
  c.a.label = "a";
  c.b.label = "b";
  for (LeaveTally* t : {&c.a.leave, &c.b.leave}) t->resize(16);
  c.a.leave.aggregate_steps_by_size[2] = 1000;  // 100 tu
  c.a.leave.escapes_by_size[2] = 4;
  c.b.leave.aggregate_steps_by_size[2] = 2000;
  c.b.leave.escapes_by_size[2] = 1;
  c.b.leave.aggregate_steps_by_size[10] = 500;  // 50 tu
  c.b.leave.escapes_by_size[10] = 9;
  const std::string csv = escape_rate_csv(a, b, c);
  std::istringstream lines(csv);
  std::string header, two, ten, none;
  std::getline(lines, header);
  std::getline(lines, two);
  std::getline(lines, ten);
  EXPECT_FALSE(std::getline(lines, none));
  EXPECT_EQ(header,
            "size,a_escapes,a_aggregate_time,a_rate,a_ci95_low,a_ci95_high,b_escapes,"
            "b_aggregate_time,b_rate,b_ci95_low,b_ci95_high,all_members_law,periphery_law");
  // Exact (Garwood) intervals, from scipy: gamma.ppf(0.025, k) / T and gamma.ppf(0.975, k + 1)
  // / T. The normal approximation gave 1 escape in 200 tu 0.005 +- 0.0098, below 0.
  const auto fields = [](const std::string& row) {
    std::vector<double> out;
    std::istringstream in(row);
    for (std::string field; std::getline(in, field, ',');) out.push_back(std::stod(field));
    return out;
  };
  const std::vector<double> at_two = fields(two);
  ASSERT_EQ(at_two.size(), 13u);
  EXPECT_EQ(std::vector<double>(at_two.begin(), at_two.begin() + 4),
            (std::vector<double>{2, 4, 100, 0.04}));
  EXPECT_NEAR(at_two[4], 0.010898653736263248, 1e-12);
  EXPECT_NEAR(at_two[5], 0.10241588675403694, 1e-12);
  EXPECT_EQ(std::vector<double>(at_two.begin() + 6, at_two.begin() + 9),
            (std::vector<double>{1, 200, 0.005}));
  EXPECT_NEAR(at_two[9], 0.00012658903992144937, 1e-15);
  EXPECT_NEAR(at_two[10], 0.027858216954694492, 1e-12);
  EXPECT_THAT(two, ::testing::EndsWith(",0.02,0.02"));
  EXPECT_THAT(ten, ::testing::StartsWith("10,0,0,NaN,NaN,NaN,9,50,0.18,"));
  const std::vector<double> at_ten = fields(ten);
  ASSERT_EQ(at_ten.size(), 13u);
  EXPECT_NEAR(at_ten[9], 0.08230746194756668, 1e-12);
  EXPECT_NEAR(at_ten[10], 0.34169606902838334, 1e-12);
  EXPECT_NEAR(at_ten[11], 0.1, 1e-12);
}

// Soysal's paper worlds set model.periphery_cap: false, and their model then lets periph(3) =
// pi (1.2 3^0.48 - 1) = 3.246 agents leave a 3-aggregate: the plotted law must be the model's.
TEST(ComparePlots, SoysalPeripheryLawFollowsTheModelsCap) {
  WorldSpec spec = tiny_world();
  spec.controller.type = "soysal";
  spec.controller.p0 = 0.001;
  spec.model.periphery_cap = false;
  const ArmResult a{"a", spec, {}, {}, {}};
  Comparison c;
  c.a.label = c.b.label = "a";
  for (LeaveTally* t : {&c.a.leave, &c.b.leave}) t->resize(8);
  c.a.leave.aggregate_steps_by_size[3] = 1000;
  const auto periphery_law = [&] {
    const std::string csv = escape_rate_csv(a, a, c);
    const std::string row = csv.substr(csv.find('\n') + 1);
    return std::stod(row.substr(row.rfind(',') + 1));
  };
  EXPECT_NEAR(periphery_law(), 3.2459 * 0.001 / spec.engine.dt, 1e-5);
  spec.model.periphery_cap = true;
  const ArmResult capped{"a", spec, {}, {}, {}};
  const std::string csv = escape_rate_csv(capped, capped, c);
  EXPECT_THAT(csv, ::testing::EndsWith(",0.03,0.03\n"));
}

}  // namespace
}  // namespace swarmagg
