#include "output/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
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

// A rename replaces whatever the path names: a pipe (or, run as root, /dev/null) given as an
// output would become a regular file. It is refused, and left as it was.
TEST(AtomicFile, APipeOrDeviceIsNeverReplaced) {
  const ScratchFolder folder("atomic-file");
  const std::filesystem::path pipe = folder.path() / "out.csv";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0644), 0);
  EXPECT_THROW(write_file_atomic(pipe, "x\n"), std::system_error);
  EXPECT_TRUE(std::filesystem::is_fifo(pipe));
  EXPECT_EQ(names_in(folder.path()), std::vector<std::string>{"out.csv"});  // no temporary
}

// Written in pieces: the target appears whole at commit(); a writer given up on (an error,
// Ctrl-C) leaves the earlier target and no temporary.
TEST(AtomicFile, AWriterInPiecesReplacesTheTargetOnlyWhenCommitted) {
  const ScratchFolder folder("atomic-file");
  write_file_atomic(folder.path() / "a.csv", "old\n");
  {
    AtomicFileWriter abandoned(folder.path() / "a.csv");
    abandoned.write("x,y\n");
  }
  EXPECT_EQ(names_in(folder.path()), std::vector<std::string>{"a.csv"});
  EXPECT_EQ(std::filesystem::file_size(folder.path() / "a.csv"), 4u);
  AtomicFileWriter writer(folder.path() / "a.csv");
  writer.write("x,y\n");
  writer.write("1,2\n");
  EXPECT_EQ(std::filesystem::file_size(folder.path() / "a.csv"), 4u) << "replaced before commit";
  writer.commit();
  EXPECT_EQ(names_in(folder.path()), std::vector<std::string>{"a.csv"});
  EXPECT_EQ(std::filesystem::file_size(folder.path() / "a.csv"), 8u);
  std::ifstream in(folder.path() / "a.csv");
  std::string first, second;
  std::getline(in, first);
  std::getline(in, second);
  EXPECT_EQ(first + ";" + second, "x,y;1,2");
}

// Writers landing together finish all, then commit: one given up on after finish() (a later
// writer failed) still leaves the earlier target and no temporary.
TEST(AtomicFile, AFinishedWriterNeverCommittedLeavesTheEarlierTarget) {
  const ScratchFolder folder("atomic-file");
  write_file_atomic(folder.path() / "a.csv", "old\n");
  {
    AtomicFileWriter finished(folder.path() / "a.csv");
    finished.write("new content\n");
    finished.finish();
    EXPECT_EQ(names_in(folder.path()).size(), 2u) << "the finished temporary is gone early";
  }
  EXPECT_EQ(names_in(folder.path()), std::vector<std::string>{"a.csv"});
  EXPECT_EQ(std::filesystem::file_size(folder.path() / "a.csv"), 4u);
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

// What a killed run left goes; what a running one writes, and anything else, stays.
TEST(AtomicFile, OnlyTemporariesOfProcessesThatAreGoneAreStale) {
  const ScratchFolder folder("atomic-file-stale");
  // Beyond Linux's largest process id: no such process.
  const std::string gone = ".timeseries.csv.99999999.0.tmp";
  const std::string scratch = ".trajectories.h5.replicate_2.99999999.3.tmp";
  const std::string running = temporary_beside(folder.path() / "summary.json").filename();
  for (const std::string& name : {gone, scratch, running, std::string(".hidden"),
                                  std::string("notes.99999999.0.tmp"), std::string("a.csv")})
    write_file_atomic(folder.path() / name, "x");
  // A killed run's staged frames: a folder so named, with frames in it.
  write_file_atomic(folder.path() / ".staged-frames.99999999.1.tmp" / "frame_000000.png", "x");
  EXPECT_EQ(remove_stale_temporaries(folder.path()), 3u);
  std::vector<std::string> left = names_in(folder.path());
  std::sort(left.begin(), left.end());
  std::vector<std::string> expected = {running, ".hidden", "a.csv", "notes.99999999.0.tmp"};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(left, expected);
}

}  // namespace
}  // namespace swarmagg
