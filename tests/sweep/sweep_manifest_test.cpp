// sweep.json read back (merge, plots): what the manifest holds is checked as the sweep file
// was, and a damaged one is refused naming the file and the field.
#include "sweep/sweep_manifest.hpp"

#include <gmock/gmock.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/errors.hpp"

namespace swarmagg {
namespace {

using ::testing::HasSubstr;

class SweepManifestTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("swarmagg_manifest_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // The error of reading a manifest whose `field` holds `value` (JSON text), or "no error".
  std::string error_with(const std::string& field, const std::string& value) {
    std::string text = R"({"name": "grid", "seed": 7, "replicates": 2, "base_world": "name: w\n",
                          "parameters": [{"key": "robots.count", "values": ["10", "20"]}]})";
    const std::size_t at = text.find("\"" + field + "\"");
    const std::size_t colon = text.find(':', at);
    const std::size_t end =
        field == "parameters" ? text.rfind('}') : text.find_first_of(",}", colon);
    text = text.substr(0, colon + 1) + " " + value + text.substr(end);
    std::ofstream(dir_ / "sweep.json", std::ios::trunc) << text;
    try {
      read_manifest(dir_);
      return "no error";
    } catch (const InputError& e) {
      return e.what();
    }
  }

  std::filesystem::path dir_;
};

TEST_F(SweepManifestTest, ADamagedManifestIsRefusedNamingTheField) {
  EXPECT_EQ(error_with("replicates", "2"), "no error");
  const SweepPlan plan = read_manifest(dir_);
  EXPECT_EQ(plan.name, "grid");
  EXPECT_EQ(plan.seed, 7u);
  EXPECT_EQ(plan.replicates, 2);
  ASSERT_EQ(plan.parameters.size(), 1u);
  EXPECT_EQ(plan.parameters[0].values, (std::vector<std::string>{"10", "20"}));
  EXPECT_EQ(error_with("seed", "18446744073709551615"), "no error");
  EXPECT_EQ(read_manifest(dir_).seed, 18446744073709551615u);
  const std::string file = (dir_ / "sweep.json").string() + ": ";
  // A negative count was a vector's length error, a huge one "out of memory", a fraction cut.
  for (const char* replicates : {"-1", "0", "2.7", "99999999999", "\"2\""}) {
    EXPECT_THAT(error_with("replicates", replicates),
                HasSubstr(file + "replicates: expected a whole number from 1 to"))
        << replicates;
  }
  // A negative seed wrapped to 2^64 - 1.
  EXPECT_THAT(error_with("seed", "-1"), HasSubstr(file + "seed: expected"));
  EXPECT_THAT(error_with("name", "3"), HasSubstr(file + "name: expected a text, got 3"));
  EXPECT_THAT(error_with("parameters", "[]"), HasSubstr(file + "parameters: expected a list"));
  EXPECT_THAT(error_with("parameters", R"([{"key": "robots.cont", "values": ["1"]}])"),
              HasSubstr(file + "parameters: expected a list of {key, values}"));
  EXPECT_THAT(error_with("parameters", R"([{"key": "robots.count", "values": []}])"),
              HasSubstr(file + "parameters: expected"));
  // Values name the runs' folders: one that climbs out of the sweep's folder is refused, and
  // so is a key the sweep sets itself.
  EXPECT_THAT(error_with("parameters", R"([{"key": "robots.count", "values": ["../.."]}])"),
              HasSubstr(file + "parameters: expected values of letters, digits"));
  EXPECT_THAT(error_with("parameters", R"([{"key": "run.replicates", "values": ["2"]}])"),
              HasSubstr(file + "parameters: expected a list of {key, values}"));
  EXPECT_THAT(error_with("parameters", R"([{"key": "robots.count", "values": ["1"]},
                                          {"key": "robots.count", "values": ["2"]}])"),
              HasSubstr(file + "parameters: expected each key once"));
}

}  // namespace
}  // namespace swarmagg
