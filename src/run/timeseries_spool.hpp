#pragma once
// A run's timeseries.csv written while the replicates run: each replicate's rows go to a
// temporary file of their own beside the target, and commit() joins them in replicate order
// under the header. A long run then holds no rows in memory (88 bytes per replicate and
// recorded step: 8.8 GB for 10 replicates of 10^7 recorded steps); the file is the same bytes
// as one written from rows held (output/timeseries_csv.hpp). Each replicate writes only its
// own file, so replicates running side by side need no lock. A spool destroyed before
// commit() (an error, Ctrl-C) removes its temporaries.
#include <cstdio>
#include <filesystem>
#include <vector>

#include "observers/timeseries_row.hpp"

namespace swarmagg {

class TimeseriesSpool {
 public:
  // Creates the target's folder when missing. A replicate's temporary is opened at its first
  // row and closed by close(), so only the replicates running at once hold a file open (a
  // run of thousands of replicates stays within the open-file limit).
  TimeseriesSpool(std::filesystem::path target, int replicates);
  // The temporaries in `parts_folder` (made when missing) instead, named after the target's
  // folder and file: for a target whose folder an earlier output still occupies until the
  // run is done (`compare --force` removes the arms' folders whole). commit() makes the
  // target's folder.
  TimeseriesSpool(std::filesystem::path target, int replicates,
                  const std::filesystem::path& parts_folder);
  ~TimeseriesSpool();
  TimeseriesSpool(const TimeseriesSpool&) = delete;
  TimeseriesSpool& operator=(const TimeseriesSpool&) = delete;

  // Throws std::system_error naming the target when the disk refuses the row.
  void append(int replicate, const TimeseriesRow& row);
  // Once the replicate has run.
  void close(int replicate);
  // Once every replicate has run: the joined file becomes the target (written atomically).
  void commit();
  const std::filesystem::path& target() const { return target_; }

 private:
  std::filesystem::path target_;
  std::vector<std::filesystem::path> parts_;
  std::vector<std::FILE*> files_;  // open from a replicate's first row to its close()

  void close_all() noexcept;
};

}  // namespace swarmagg
