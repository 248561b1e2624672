// The scratch folder's place: the system's temporary directory, read as POSIX and Python do.
#include "output/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace swarmagg {
namespace {

// Sets $TMPDIR for the scope (unset with nullopt), then puts the earlier value back.
class TmpdirAs {
 public:
  explicit TmpdirAs(std::optional<std::string> value) {
    if (const char* now = std::getenv("TMPDIR")) earlier_ = now;
    if (value)
      ::setenv("TMPDIR", value->c_str(), 1);
    else
      ::unsetenv("TMPDIR");
  }
  ~TmpdirAs() {
    if (earlier_)
      ::setenv("TMPDIR", earlier_->c_str(), 1);
    else
      ::unsetenv("TMPDIR");
  }

 private:
  std::optional<std::string> earlier_;
};

// An empty $TMPDIR is no setting, as Python's tempfile reads it (summary() of a Python Run
// failed there with "no temporary directory").
TEST(ScratchFolder, AnEmptyOrUnsetTmpdirMeansTmp) {
  for (const std::optional<std::string>& value :
       {std::optional<std::string>(""), std::optional<std::string>()}) {
    const TmpdirAs setting(value);
    const ScratchFolder folder("scratch-test");
    EXPECT_EQ(folder.path().parent_path(), std::filesystem::path("/tmp"));
    EXPECT_TRUE(std::filesystem::is_directory(folder.path()));
  }
}

TEST(ScratchFolder, AMissingTmpdirIsNamedInTheError) {
  const TmpdirAs setting(std::string("/nonexistent-swarmagg-tmpdir"));
  try {
    const ScratchFolder folder("scratch-test");
    FAIL() << "made " << folder.path();
  } catch (const std::filesystem::filesystem_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-swarmagg-tmpdir"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace swarmagg
