#include "output/made_folders.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "output/scratch_folder.hpp"

namespace swarmagg {
namespace {

namespace fs = std::filesystem;

TEST(MadeFolders, RemovesWhatItMadeAndNothingAbove) {
  const ScratchFolder scratch("swarmagg-made-folders");
  const MadeFolders made(scratch.path() / "runs" / "p1" / "rep-0");
  ASSERT_TRUE(fs::is_directory(scratch.path() / "runs" / "p1" / "rep-0"));
  made.remove_if_empty();
  EXPECT_FALSE(fs::exists(scratch.path() / "runs"));
  EXPECT_TRUE(fs::is_directory(scratch.path()));
}

TEST(MadeFolders, AFolderHoldingAFileStaysWithTheFoldersAboveIt) {
  const ScratchFolder scratch("swarmagg-made-folders");
  const MadeFolders made(scratch.path() / "runs" / "p1" / "rep-0");
  std::ofstream(scratch.path() / "runs" / "p1" / "theirs.txt") << "x";
  made.remove_if_empty();
  EXPECT_FALSE(fs::exists(scratch.path() / "runs" / "p1" / "rep-0"));
  EXPECT_TRUE(fs::exists(scratch.path() / "runs" / "p1" / "theirs.txt"));
}

TEST(MadeFolders, RemovedOnFailureOnlyWhenTheScopeThrows) {
  const ScratchFolder scratch("swarmagg-made-folders");
  {
    const MadeFolders made(scratch.path() / "kept");
    const RemovedOnFailure unmade(made);
  }
  EXPECT_TRUE(fs::is_directory(scratch.path() / "kept"));
  try {
    const MadeFolders made(scratch.path() / "failed" / "run");
    const RemovedOnFailure unmade(made);
    throw std::runtime_error("the run failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(scratch.path() / "failed"));
}

// A sibling run removes runs/<point>/ (empty: it failed) after it was found and before the
// folder inside it is made: the chain is made again, and the point folder is this one's now.
TEST(MakeFolders, AParentThatVanishesIsMadeAgain) {
  const ScratchFolder scratch("swarmagg-made-folders");
  const fs::path point = scratch.path() / "runs" / "point", mine = point / "rep-0";
  fs::create_directories(point);
  bool removed = false;
  const auto sibling_fails = [&](const fs::path& folder) {
    if (folder == mine && !removed) {
      removed = fs::remove(point);
      return ENOENT;
    }
    return make_one_folder(folder);
  };
  std::error_code error;
  EXPECT_EQ(make_folders(mine, error, sibling_fails), point);
  EXPECT_FALSE(error) << error.message();
  EXPECT_TRUE(removed);
  EXPECT_TRUE(fs::is_directory(mine));
}

// The sibling made the point folder first (EEXIST) and removed it before this one made its
// own inside: create_directories reported "File exists" there.
TEST(MakeFolders, AParentMadeAndRemovedByASiblingIsMadeAgain) {
  const ScratchFolder scratch("swarmagg-made-folders");
  const fs::path runs = scratch.path() / "runs", point = runs / "point", mine = point / "rep-0";
  bool raced = false;
  const auto sibling_makes_and_removes = [&](const fs::path& folder) {
    if (folder == point && !raced) {
      raced = true;
      return EEXIST;  // the sibling's folder, already gone
    }
    return make_one_folder(folder);
  };
  std::error_code error;
  EXPECT_EQ(make_folders(mine, error, sibling_makes_and_removes), runs);
  EXPECT_FALSE(error) << error.message();
  EXPECT_TRUE(raced);
  EXPECT_TRUE(fs::is_directory(mine));
}

TEST(MakeFolders, OtherFailuresAreReportedWithWhatWasMade) {
  const ScratchFolder scratch("swarmagg-made-folders");
  const fs::path runs = scratch.path() / "runs";
  const auto denied = [&](const fs::path& folder) {
    return folder == runs ? make_one_folder(folder) : EACCES;
  };
  std::error_code error;
  EXPECT_EQ(make_folders(runs / "point", error, denied), runs);
  EXPECT_EQ(error, std::errc::permission_denied);
  std::ofstream(scratch.path() / "file") << "x";
  EXPECT_EQ(make_folders(scratch.path() / "file", error), fs::path());
  EXPECT_EQ(error, std::errc::file_exists);
  make_folders(scratch.path() / "file" / "inside", error);
  EXPECT_EQ(error, std::errc::not_a_directory);
  EXPECT_THROW(MadeFolders(scratch.path() / "file"), fs::filesystem_error);
}

// A sweep's parallel runs share runs/<point>/; a failing run removes it while empty, and a
// sibling about to make its own folder inside must make the point folder again rather than
// fail. The race is timing-dependent: create_directories in place of make_folders fails this
// test in about a third of runs of this size (measured); the tests above are deterministic.
TEST(MadeFolders, SiblingsMakeTheirFoldersWhileOthersRemoveTheSharedParent) {
  const ScratchFolder scratch("swarmagg-made-folders");
  std::atomic<int> failed{0};
  auto make_and_remove = [&](const std::string& leaf) {
    for (int i = 0; i < 4000; ++i) {
      try {
        const MadeFolders made(scratch.path() / "runs" / "point" / leaf);
        if (!fs::is_directory(scratch.path() / "runs" / "point" / leaf)) ++failed;
        made.remove_if_empty();
      } catch (const fs::filesystem_error&) {
        ++failed;
      }
    }
  };
  std::vector<std::thread> runs;
  for (int r = 0; r < 4; ++r) runs.emplace_back(make_and_remove, "rep-" + std::to_string(r));
  for (std::thread& run : runs) run.join();
  // (An empty runs/ may stay: whoever made it can find it in use by a sibling when it fails.)
  EXPECT_EQ(failed.load(), 0);
}

}  // namespace
}  // namespace swarmagg
