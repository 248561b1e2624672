#include "output/atomic_file.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "output/scratch_folder.hpp"

namespace swarmagg {
namespace {

std::vector<std::string> names_in(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    names.push_back(entry.path().filename().string());
  return names;
}

TEST(AtomicFile, WritesTheWholeContent) {
  const ScratchFolder folder("atomic-file");
  write_file_atomic(folder.path() / "a.csv", "x,y\n1,2\n");
  write_file_atomic(folder.path() / "a.csv", "x\n");
  EXPECT_EQ(names_in(folder.path()), std::vector<std::string>{"a.csv"});
  EXPECT_EQ(std::filesystem::file_size(folder.path() / "a.csv"), 2u);
}

// A target the system will not replace (a folder of that name) is an error naming it, with
// its errno, and the temporary written beside it is gone.
TEST(AtomicFile, AFailedRenameLeavesNoTemporary) {
  const ScratchFolder folder("atomic-file");
  std::filesystem::create_directory(folder.path() / "a.csv");
  try {
    write_file_atomic(folder.path() / "a.csv", "x\n");
    FAIL() << "wrote over a folder";
  } catch (const std::system_error& e) {
    EXPECT_EQ(e.code().value(), EISDIR);
    EXPECT_NE(std::string(e.what()).find("a.csv"), std::string::npos) << e.what();
  }
  EXPECT_EQ(names_in(folder.path()), std::vector<std::string>{"a.csv"});
}

}  // namespace
}  // namespace swarmagg
