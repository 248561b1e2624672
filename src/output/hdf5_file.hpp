#pragma once
// A thin RAII layer over the HDF5 C API (Debian's libhdf5, serial): owned handles, typed
// attributes and 1-D/2-D datasets, and errors as exceptions instead of HDF5's printed stack.
// Only what trajectories.h5 needs.
//
// Threads: every call here takes hdf5_lock() (recursive, so a handle may close inside a
// locked section), because replicates record from parallel threads and a serial HDF5 build
// must not be entered twice at once. Callers making several calls that belong together
// (a whole block of rows) hold hdf5_lock() around them.
#include <hdf5.h>

#include <cstdint>
#include <mutex>
#include <span>
#include <string>
#include <vector>

namespace swarmagg::h5 {

std::recursive_mutex& hdf5_lock();

// The CLI calls this first: HDF5's own clean-up at exit closes again the objects whose close
// failed (a full disk) and crashes doing so; every file is closed here explicitly, so the
// clean-up has nothing to do in a program that went well. (Not in the Python module, whose
// process may share the library with h5py.)
void skip_hdf5_exit_cleanup();

// An hid_t that closes itself (H5Fclose, H5Gclose, ... chosen by the id's type).
class Handle {
 public:
  Handle() = default;
  explicit Handle(hid_t id, const std::string& what);  // throws std::runtime_error if id < 0
  ~Handle();
  Handle(Handle&& other) noexcept : id_(other.id_) { other.id_ = -1; }
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t id() const { return id_; }
  void close();  // closes now and throws if HDF5 reports an error (a file's final flush)

 private:
  hid_t id_ = -1;
};

// The element types used here, as HDF5 native types.
template <typename T>
hid_t native_type();

Handle create_file(const std::string& path);  // truncates
Handle open_file_read(const std::string& path);
Handle create_group(const Handle& parent, const std::string& name);
Handle open_group(const Handle& parent, const std::string& name);
bool has_child(const Handle& parent, const std::string& name);
// Copies the object `name` (a group with everything below it) of `source` into `destination`
// under the same name. Compressed chunks move as they are: nothing is compressed again.
void copy_object(const Handle& source, const std::string& name, const Handle& destination);

void write_attribute(const Handle& object, const std::string& name, const std::string& value);
void write_attribute(const Handle& object, const std::string& name, std::int64_t value);
void write_attribute(const Handle& object, const std::string& name,
                     std::span<const std::uint64_t> values);
std::string read_string_attribute(const Handle& object, const std::string& name);
std::int64_t read_int_attribute(const Handle& object, const std::string& name);

// A 2-D dataset of rows x columns, chunked chunk_rows x chunk_columns, shuffled and
// deflated (rows = 1 or columns = 1 for a 1-D one: pass columns = 0).
Handle create_dataset(const Handle& parent, const std::string& name, hid_t type, std::int64_t rows,
                      std::int64_t columns, std::int64_t chunk_rows, std::int64_t chunk_columns,
                      int deflate_level);
Handle open_dataset(const Handle& parent, const std::string& name);
// Dimensions of a dataset: {rows} or {rows, columns}.
std::vector<std::int64_t> dataset_shape(const Handle& dataset);

// Writes `count` rows starting at `first_row` from `values` (count * columns elements).
template <typename T>
void write_rows(const Handle& dataset, std::int64_t first_row, std::int64_t count,
                std::span<const T> values);
// Reads `count` rows starting at `first_row` into `values` (resized to count * columns).
template <typename T>
void read_rows(const Handle& dataset, std::int64_t first_row, std::int64_t count,
               std::vector<T>& values);

}  // namespace swarmagg::h5
