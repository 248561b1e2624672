#include "output/hdf5_file.hpp"

#include <stdexcept>
#include <utility>

namespace swarmagg::h5 {
namespace {

using Lock = std::lock_guard<std::recursive_mutex>;

// HDF5 prints its error stack to stderr by default; errors here become exceptions instead.
// HDF5 keeps its error printing per thread: each thread that calls it is silenced once.
void silence_hdf5_errors() {
  thread_local const bool silenced = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)silenced;
}

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: cannot " + what);
}

Handle dataspace(std::span<const hsize_t> dims, const std::string& what) {
  return Handle(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), what);
}

// The file space of a dataset with rows [first_row, first_row + count) selected, and the
// matching memory space.
std::pair<Handle, Handle> row_selection(const Handle& dataset, std::int64_t first_row,
                                        std::int64_t count) {
  Handle file_space(H5Dget_space(dataset.id()), "get a dataset's space");
  hsize_t dims[2] = {0, 0};
  const int rank = H5Sget_simple_extent_dims(file_space.id(), dims, nullptr);
  if (rank < 1) throw std::runtime_error("HDF5: dataset of unexpected rank");
  if (first_row < 0 || count < 0 || static_cast<hsize_t>(first_row + count) > dims[0]) {
    throw std::runtime_error("HDF5: rows " + std::to_string(first_row) + "+" +
                             std::to_string(count) + " outside a dataset of " +
                             std::to_string(dims[0]) + " rows");
  }
  hsize_t start[2] = {static_cast<hsize_t>(first_row), 0};
  hsize_t extent[2] = {static_cast<hsize_t>(count), dims[1]};
  check(H5Sselect_hyperslab(file_space.id(), H5S_SELECT_SET, start, nullptr, extent, nullptr),
        "select rows");
  Handle memory_space = dataspace(std::span<const hsize_t>(extent, rank), "make a row space");
  return {std::move(file_space), std::move(memory_space)};
}

std::size_t row_elements(const Handle& dataset, std::int64_t count) {
  const auto shape = dataset_shape(dataset);
  return static_cast<std::size_t>(count) *
         static_cast<std::size_t>(shape.size() > 1 ? shape[1] : 1);
}

}  // namespace

std::recursive_mutex& hdf5_lock() {
  static std::recursive_mutex lock;
  return lock;
}

void skip_hdf5_exit_cleanup() {
  H5dont_atexit();
}

Handle::Handle(hid_t id, const std::string& what) : id_(id) {
  if (id_ < 0) throw std::runtime_error("HDF5: cannot " + what);
}

Handle::~Handle() {
  if (id_ < 0) return;
  Lock lock(hdf5_lock());
  silence_hdf5_errors();
  H5Idec_ref(id_);  // closes any kind of object; errors cannot be reported from here
}

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    Handle dropped(std::move(*this));
    id_ = std::exchange(other.id_, -1);
  }
  return *this;
}

void Handle::close() {
  if (id_ < 0) return;
  Lock lock(hdf5_lock());
  silence_hdf5_errors();
  const hid_t id = std::exchange(id_, -1);
  const bool is_file = H5Iget_type(id) == H5I_FILE;
  check(is_file ? H5Fclose(id) : H5Idec_ref(id), "close an object (disk full?)");
}

template <>
hid_t native_type<double>() {
  return H5T_NATIVE_DOUBLE;
}
template <>
hid_t native_type<float>() {
  return H5T_NATIVE_FLOAT;
}
template <>
hid_t native_type<std::int64_t>() {
  return H5T_NATIVE_INT64;
}
template <>
hid_t native_type<std::int32_t>() {
  return H5T_NATIVE_INT32;
}
template <>
hid_t native_type<std::uint8_t>() {
  return H5T_NATIVE_UINT8;
}
template <>
hid_t native_type<std::uint64_t>() {
  return H5T_NATIVE_UINT64;
}

Handle create_file(const std::string& path) {
  Lock lock(hdf5_lock());
  silence_hdf5_errors();
  // Closing the file fails while a group or dataset is still open, instead of deferring
  // the close (and the last writes) to whenever that object goes.
  Handle access(H5Pcreate(H5P_FILE_ACCESS), "make file properties");
  check(H5Pset_fclose_degree(access.id(), H5F_CLOSE_SEMI), "set the file close degree");
  return Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.id()), "create " + path);
}

Handle open_file_read(const std::string& path) {
  Lock lock(hdf5_lock());
  silence_hdf5_errors();
  return Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "open " + path);
}

Handle create_group(const Handle& parent, const std::string& name) {
  Lock lock(hdf5_lock());
  Handle properties(H5Pcreate(H5P_GROUP_CREATE), "make group properties");
  check(H5Pset_obj_track_times(properties.id(), false), "untime group " + name);
  return Handle(H5Gcreate2(parent.id(), name.c_str(), H5P_DEFAULT, properties.id(), H5P_DEFAULT),
                "create group " + name);
}

Handle open_group(const Handle& parent, const std::string& name) {
  Lock lock(hdf5_lock());
  return Handle(H5Gopen2(parent.id(), name.c_str(), H5P_DEFAULT), "open group " + name);
}

bool has_child(const Handle& parent, const std::string& name) {
  Lock lock(hdf5_lock());
  return H5Lexists(parent.id(), name.c_str(), H5P_DEFAULT) > 0;
}

void copy_object(const Handle& source, const std::string& name, const Handle& destination) {
  Lock lock(hdf5_lock());
  check(
      H5Ocopy(source.id(), name.c_str(), destination.id(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
      "copy " + name + " (disk full?)");
}

void write_attribute(const Handle& object, const std::string& name, const std::string& value) {
  Lock lock(hdf5_lock());
  // A variable-length UTF-8 string: h5py reads it as a Python str.
  Handle type(H5Tcopy(H5T_C_S1), "copy the string type");
  check(H5Tset_size(type.id(), H5T_VARIABLE), "size a string type");
  check(H5Tset_cset(type.id(), H5T_CSET_UTF8), "set a string's character set");
  Handle space(H5Screate(H5S_SCALAR), "make a scalar space");
  Handle attribute(
      H5Acreate2(object.id(), name.c_str(), type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT),
      "create attribute " + name);
  const char* text = value.c_str();
  check(H5Awrite(attribute.id(), type.id(), &text), "write attribute " + name);
}

void write_attribute(const Handle& object, const std::string& name, std::int64_t value) {
  Lock lock(hdf5_lock());
  Handle space(H5Screate(H5S_SCALAR), "make a scalar space");
  Handle attribute(
      H5Acreate2(object.id(), name.c_str(), H5T_STD_I64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT),
      "create attribute " + name);
  check(H5Awrite(attribute.id(), H5T_NATIVE_INT64, &value), "write attribute " + name);
}

void write_attribute(const Handle& object, const std::string& name,
                     std::span<const std::uint64_t> values) {
  Lock lock(hdf5_lock());
  const hsize_t dims[1] = {values.size()};
  Handle space = dataspace(dims, "make an attribute space");
  Handle attribute(
      H5Acreate2(object.id(), name.c_str(), H5T_STD_U64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT),
      "create attribute " + name);
  check(H5Awrite(attribute.id(), H5T_NATIVE_UINT64, values.data()), "write attribute " + name);
}

std::string read_string_attribute(const Handle& object, const std::string& name) {
  Lock lock(hdf5_lock());
  Handle attribute(H5Aopen(object.id(), name.c_str(), H5P_DEFAULT), "open attribute " + name);
  Handle type(H5Tcopy(H5T_C_S1), "copy the string type");
  check(H5Tset_size(type.id(), H5T_VARIABLE), "size a string type");
  check(H5Tset_cset(type.id(), H5T_CSET_UTF8), "set a string's character set");
  char* text = nullptr;
  check(H5Aread(attribute.id(), type.id(), &text), "read attribute " + name);
  std::string value = text != nullptr ? text : "";
  H5free_memory(text);
  return value;
}

std::int64_t read_int_attribute(const Handle& object, const std::string& name) {
  Lock lock(hdf5_lock());
  Handle attribute(H5Aopen(object.id(), name.c_str(), H5P_DEFAULT), "open attribute " + name);
  std::int64_t value = 0;
  check(H5Aread(attribute.id(), H5T_NATIVE_INT64, &value), "read attribute " + name);
  return value;
}

Handle create_dataset(const Handle& parent, const std::string& name, hid_t type, std::int64_t rows,
                      std::int64_t columns, std::int64_t chunk_rows, std::int64_t chunk_columns,
                      int deflate_level) {
  Lock lock(hdf5_lock());
  const int rank = columns > 0 ? 2 : 1;
  const hsize_t dims[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(columns)};
  const hsize_t chunk[2] = {static_cast<hsize_t>(std::max<std::int64_t>(1, chunk_rows)),
                            static_cast<hsize_t>(std::max<std::int64_t>(1, chunk_columns))};
  Handle space = dataspace(std::span<const hsize_t>(dims, rank), "make a dataset space");
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), "make dataset properties");
  check(H5Pset_chunk(properties.id(), rank, chunk), "chunk " + name);
  // Byte shuffling groups the slowly varying high bytes of numbers: deflate then finds
  // runs it would miss in raw doubles.
  check(H5Pset_shuffle(properties.id()), "shuffle " + name);
  check(H5Pset_deflate(properties.id(), static_cast<unsigned>(deflate_level)), "deflate " + name);
  // No modification times: the same run writes the same bytes.
  check(H5Pset_obj_track_times(properties.id(), false), "untime dataset " + name);
  return Handle(H5Dcreate2(parent.id(), name.c_str(), type, space.id(), H5P_DEFAULT,
                           properties.id(), H5P_DEFAULT),
                "create dataset " + name);
}

Handle open_dataset(const Handle& parent, const std::string& name) {
  Lock lock(hdf5_lock());
  return Handle(H5Dopen2(parent.id(), name.c_str(), H5P_DEFAULT), "open dataset " + name);
}

std::vector<std::int64_t> dataset_shape(const Handle& dataset) {
  Lock lock(hdf5_lock());
  Handle space(H5Dget_space(dataset.id()), "get a dataset's space");
  hsize_t dims[H5S_MAX_RANK] = {};
  const int rank = H5Sget_simple_extent_dims(space.id(), dims, nullptr);
  if (rank < 0) throw std::runtime_error("HDF5: cannot read a dataset's shape");
  return std::vector<std::int64_t>(dims, dims + rank);
}

template <typename T>
void write_rows(const Handle& dataset, std::int64_t first_row, std::int64_t count,
                std::span<const T> values) {
  Lock lock(hdf5_lock());
  if (values.size() != row_elements(dataset, count)) {
    throw std::logic_error("HDF5 write_rows: values do not fill the rows");
  }
  const auto [file_space, memory_space] = row_selection(dataset, first_row, count);
  check(H5Dwrite(dataset.id(), native_type<T>(), memory_space.id(), file_space.id(), H5P_DEFAULT,
                 values.data()),
        "write rows (disk full?)");
}

template <typename T>
void read_rows(const Handle& dataset, std::int64_t first_row, std::int64_t count,
               std::vector<T>& values) {
  Lock lock(hdf5_lock());
  values.resize(row_elements(dataset, count));
  const auto [file_space, memory_space] = row_selection(dataset, first_row, count);
  check(H5Dread(dataset.id(), native_type<T>(), memory_space.id(), file_space.id(), H5P_DEFAULT,
                values.data()),
        "read rows");
}

#define SWARMAGG_H5_ROWS(T)                                                                   \
  template void write_rows<T>(const Handle&, std::int64_t, std::int64_t, std::span<const T>); \
  template void read_rows<T>(const Handle&, std::int64_t, std::int64_t, std::vector<T>&);
SWARMAGG_H5_ROWS(double)
SWARMAGG_H5_ROWS(float)
SWARMAGG_H5_ROWS(std::int64_t)
SWARMAGG_H5_ROWS(std::int32_t)
SWARMAGG_H5_ROWS(std::uint8_t)
#undef SWARMAGG_H5_ROWS

}  // namespace swarmagg::h5
