#pragma once
// Outputs are written to a temporary file beside the target and renamed over it, so an
// interrupted run leaves either the previous file or the complete new one, never half.
#include <cstdio>
#include <filesystem>
#include <string_view>

namespace swarmagg {

void write_file_atomic(const std::filesystem::path& target, std::string_view content);

// The same promise for a text written piece by piece, too large to hold whole (a long
// model's CSV files reach gigabytes): the pieces go to the temporary, and commit() syncs it
// and renames it over the target. A writer destroyed before commit() (an error, Ctrl-C)
// removes its temporary, so the target keeps its earlier content.
class AtomicFileWriter {
 public:
  // Creates the target's folder when missing, and the temporary.
  explicit AtomicFileWriter(std::filesystem::path target);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  // Throws std::system_error naming the target when the disk refuses the piece.
  void write(std::string_view piece);
  // Once the content is complete: syncs the temporary to disk and closes it. Writers that
  // land together finish all before the first commits, so that a full disk stops them all.
  void finish();
  // Once (after finish(), or doing it): the temporary becomes the target.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::FILE* file_ = nullptr;  // until finished
  bool committed_ = false;
};

// For outputs that a library writes itself (HDF5): a fresh hidden temporary path beside
// `target` (".<name>.<pid>.<n>.tmp"), and, once the file there is complete and closed,
// commit_temporary() syncs it to disk and renames it over `target`.
std::filesystem::path temporary_beside(const std::filesystem::path& target);
void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& target);

// Whether `path` names a device, pipe or socket (not following a link): a rename over it would
// replace the node with a regular file, so no output is ever written there.
bool is_special_file(const std::filesystem::path& path);

// Renames the complete `temporary` over `target` (no sync: for outputs cheap to make again,
// such as frames). When the system refuses (a folder of that name, say), the temporary is
// removed and std::system_error names `target`: a failed output leaves nothing behind.
void rename_or_discard(const std::filesystem::path& temporary, const std::filesystem::path& target);
// Removes a temporary that will not become its output, whatever removing it says.
void discard_temporary(const std::filesystem::path& temporary);
// Removes the temporaries in `folder` (files or folders named as temporary_beside names them)
// whose process is gone: what a killed run (SIGKILL, a node lost) left. Those of running processes
// stay, as far as this machine can tell: a process id is looked up here, so a run on another node
// writing to the same shared folder (or in another PID namespace) would lose its
// temporaries. Returns how many were removed.
std::size_t remove_stale_temporaries(const std::filesystem::path& folder);

}  // namespace swarmagg
