#include "run/timeseries_spool.hpp"

#include <cerrno>
#include <string>
#include <system_error>

#include "output/atomic_file.hpp"
#include "output/timeseries_csv.hpp"

namespace swarmagg {
namespace {

constexpr std::size_t kCopyChunk = 1 << 20;

[[noreturn]] void cannot_write(const std::filesystem::path& target, int error = errno) {
  throw std::system_error(error, std::generic_category(), "cannot write " + target.string());
}

}  // namespace

TimeseriesSpool::TimeseriesSpool(std::filesystem::path target, int replicates)
    : TimeseriesSpool(target, replicates, target.parent_path()) {}

TimeseriesSpool::TimeseriesSpool(std::filesystem::path target, int replicates,
                                 const std::filesystem::path& parts_folder)
    : target_(std::move(target)), files_(static_cast<std::size_t>(replicates), nullptr) {
  if (!parts_folder.empty()) std::filesystem::create_directories(parts_folder);
  // Beside the target, or named after its folder too (.kinematic-timeseries.csv.*).
  const std::string folder_name = target_.parent_path().filename().string();
  const std::filesystem::path part_name =
      target_.parent_path() == parts_folder || folder_name.empty()
          ? parts_folder / target_.filename()
          : parts_folder / (folder_name + "-" + target_.filename().string());
  for (int r = 0; r < replicates; ++r) parts_.push_back(temporary_beside(part_name));
}

TimeseriesSpool::~TimeseriesSpool() {
  close_all();
  for (const std::filesystem::path& part : parts_) discard_temporary(part);
}

void TimeseriesSpool::close_all() noexcept {
  for (std::FILE*& file : files_) {
    if (file != nullptr) std::fclose(file);
    file = nullptr;
  }
}

void TimeseriesSpool::append(int replicate, const TimeseriesRow& row) {
  std::FILE*& file = files_.at(static_cast<std::size_t>(replicate));
  if (file == nullptr) {
    file = std::fopen(parts_[static_cast<std::size_t>(replicate)].c_str(), "wbe");
    if (file == nullptr) cannot_write(target_);
  }
  const std::string line = timeseries_csv_line(row) + "\n";
  if (std::fwrite(line.data(), 1, line.size(), file) != line.size()) cannot_write(target_);
}

void TimeseriesSpool::close(int replicate) {
  std::FILE*& file = files_.at(static_cast<std::size_t>(replicate));
  if (file == nullptr) return;
  const bool closed = std::fclose(file) == 0;
  file = nullptr;
  if (!closed) cannot_write(target_);
}

void TimeseriesSpool::commit() {
  for (std::size_t r = 0; r < files_.size(); ++r) close(static_cast<int>(r));
  AtomicFileWriter joined(target_);
  joined.write(std::string(kTimeseriesHeader) + "\n");
  std::string chunk(kCopyChunk, '\0');
  // Each part goes once copied: the disk holds the rows about once, not twice.
  for (const std::filesystem::path& part : parts_) {
    std::FILE* file = std::fopen(part.c_str(), "rbe");
    if (file == nullptr) cannot_write(target_);
    std::size_t read = 0;
    while ((read = std::fread(chunk.data(), 1, chunk.size(), file)) > 0)
      joined.write(std::string_view(chunk.data(), read));
    const int read_error = std::ferror(file) != 0 ? errno : 0;
    std::fclose(file);
    if (read_error != 0) cannot_write(target_, read_error);
    discard_temporary(part);
  }
  joined.commit();
  parts_.clear();
}

}  // namespace swarmagg
