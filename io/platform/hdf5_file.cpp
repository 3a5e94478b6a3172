#include "flexure/io/platform/hdf5_file.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <mutex>
#include <utility>

#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/io/platform/temp_file_cleanup.h"

namespace flexure::io {

namespace detail {
// How a file is written, shared by its groups (hdf5_file.h Hdf5Access).
struct Hdf5FileState {
  bool collective = false;   // kCollective with more than one rank
  bool writes_whole = true;  // this rank writes datasets given whole (rank 0)
  // String datasets of a collective file, written by rank 0 in commit().
  struct DeferredStrings {
    std::string group_path, name, units, description;
    std::vector<std::string> values;
  };
  std::vector<DeferredStrings> deferred;
};
}  // namespace detail

namespace {

// Closes an HDF5 identifier when leaving scope; close failures in cleanup paths are ignored
// because the operation that needed the object has already succeeded or thrown.
class ScopedId {
 public:
  using Closer = herr_t (*)(hid_t);
  ScopedId(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  ScopedId(const ScopedId&) = delete;
  ScopedId& operator=(const ScopedId&) = delete;
  ~ScopedId() {
    if (id_ >= 0) closer_(id_);
  }
  hid_t get() const { return id_; }
  hid_t release() { return std::exchange(id_, H5I_INVALID_HID); }

 private:
  hid_t id_;
  Closer closer_;
};

// A group or dataset of a collective file is left open while an exception unwinds: closing it
// may be a collective call, and this rank may be the only one failing. The ranks then agree to
// end (cli/cli_common.cpp) and HDF5 closes what is left before MPI ends (parallel/mpi_world.h
// finalize), or one rank ends them all with MPI_Abort.
bool leave_open_while_unwinding(bool collective) {
  return collective && std::uncaught_exceptions() > 0;
}

hid_t check_id(hid_t id, const std::string& where, const char* what) {
  if (id < 0) throw Hdf5Error(fmt::format("HDF5: {} failed for {}", what, where));
  return id;
}

void check_status(herr_t status, const std::string& where, const char* what) {
  if (status < 0) throw Hdf5Error(fmt::format("HDF5: {} failed for {}", what, where));
}

// A UTF-8 variable-length string type (read back as str by h5py and as char* by the C API).
hid_t make_string_type(const std::string& where) {
  hid_t type = check_id(H5Tcopy(H5T_C_S1), where, "copying the string type");
  if (H5Tset_size(type, H5T_VARIABLE) < 0 || H5Tset_cset(type, H5T_CSET_UTF8) < 0) {
    H5Tclose(type);
    throw Hdf5Error(fmt::format("HDF5: setting up a UTF-8 string type failed for {}", where));
  }
  return type;
}

// Writes a scalar UTF-8 string attribute on any object (group or dataset).
void write_string_attribute(hid_t object,
                            const std::string& name,
                            const std::string& value,
                            const std::string& where) {
  ScopedId type(make_string_type(where), H5Tclose);
  ScopedId space(check_id(H5Screate(H5S_SCALAR), where, "creating the dataspace"), H5Sclose);
  ScopedId attribute(
      check_id(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
               where,
               "creating the attribute"),
      H5Aclose);
  const char* pointer = value.c_str();
  check_status(H5Awrite(attribute.get(), type.get(), &pointer), where, "writing the attribute");
}

}  // namespace

void disable_hdf5_error_printing() {
  static std::once_flag flag;
  std::call_once(flag, [] { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); });
}

// ---------------------------------------------------------------------------------------------
// Hdf5Group

Hdf5Group::Hdf5Group(hid_t id,
                     std::string file_path,
                     std::string group_path,
                     std::shared_ptr<detail::Hdf5FileState> state)
    : id_(id),
      file_path_(std::move(file_path)),
      group_path_(std::move(group_path)),
      state_(std::move(state)) {}

Hdf5Group::Hdf5Group(Hdf5Group&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)),
      file_path_(std::move(other.file_path_)),
      group_path_(std::move(other.group_path_)),
      state_(std::move(other.state_)) {}

Hdf5Group& Hdf5Group::operator=(Hdf5Group&& other) noexcept {
  if (this != &other) {
    if (id_ >= 0) H5Gclose(id_);
    id_ = std::exchange(other.id_, H5I_INVALID_HID);
    file_path_ = std::move(other.file_path_);
    group_path_ = std::move(other.group_path_);
    state_ = std::move(other.state_);
  }
  return *this;
}

Hdf5Group::~Hdf5Group() {
  if (leave_open_while_unwinding(collective())) return;
  // After the file was closed with H5F_CLOSE_STRONG the id is no longer valid; H5Iis_valid
  // avoids closing an identifier HDF5 may have reused.
  if (id_ >= 0 && H5Iis_valid(id_) > 0) H5Gclose(id_);
}

bool Hdf5Group::collective() const { return state_ && state_->collective; }

std::string Hdf5Group::where() const { return fmt::format("{}:{}", file_path_, group_path_); }

std::string Hdf5Group::child_path(const std::string& name) const {
  return group_path_ == "/" ? "/" + name : group_path_ + "/" + name;
}

Hdf5Group Hdf5Group::create_group(const std::string& name) {
  const std::string path = child_path(name);
  const std::string where = fmt::format("group '{}' in {}", path, file_path_);
  if (name.empty() || name.find('/') != std::string::npos) {
    throw Hdf5Error(fmt::format("HDF5: invalid group name for {}", where));
  }
  hid_t id = check_id(H5Gcreate2(id_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                      where,
                      "creating the group");
  return Hdf5Group(id, file_path_, path, state_);
}

hid_t Hdf5Group::create_described(const std::string& name,
                                  hid_t type,
                                  hid_t space,
                                  hid_t dcpl,
                                  const std::string& units,
                                  const std::string& description) {
  const std::string where = fmt::format("dataset '{}' in {}", child_path(name), file_path_);
  // Checked before anything is created: a file is self-describing or not written at all.
  if (units.empty()) throw Hdf5Error(fmt::format("HDF5: no units given for {}", where));
  if (description.empty() || description.find('\n') != std::string::npos) {
    throw Hdf5Error(fmt::format("HDF5: the description of {} must be one non-empty line", where));
  }
  ScopedId dataset(
      check_id(H5Dcreate2(id_, name.c_str(), type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
               where,
               "creating the dataset"),
      H5Dclose);
  write_string_attribute(dataset.get(), "units", units, where + " (attribute 'units')");
  write_string_attribute(
      dataset.get(), "description", description, where + " (attribute 'description')");
  return dataset.release();
}

void Hdf5Group::write_described(const std::string& name,
                                hid_t type,
                                hid_t space,
                                const void* data,
                                const std::string& units,
                                const std::string& description) {
  const std::string where = fmt::format("dataset '{}' in {}", child_path(name), file_path_);
  ScopedId dataset(create_described(name, type, space, H5P_DEFAULT, units, description), H5Dclose);
  // A collective file: created by every rank, its values written by rank 0 (independent transfer).
  if (data != nullptr && (!state_ || state_->writes_whole)) {
    check_status(H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                 where,
                 "writing the data");
  }
}

Hdf5Dataset Hdf5Group::create_dataset(const std::string& name,
                                      Hdf5Type type,
                                      const std::vector<hsize_t>& dims,
                                      const std::string& units,
                                      const std::string& description,
                                      const Hdf5DatasetOptions& options) {
  const std::string where = fmt::format("dataset '{}' in {}", child_path(name), file_path_);
  if (dims.empty() || dims.size() > 8) {
    throw Hdf5Error(fmt::format("HDF5: {} must have rank 1 to 8", where));
  }
  if (options.compress && dims.size() > 2) {
    throw Hdf5Error(fmt::format("HDF5: {} can be compressed only with rank 1 or 2", where));
  }
  const hid_t memory_type = type == Hdf5Type::kFloat64 ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT;
  ScopedId space(check_id(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                          where,
                          "creating the dataspace"),
                 H5Sclose);
  ScopedId dcpl(check_id(H5Pcreate(H5P_DATASET_CREATE), where, "creating the properties"),
                H5Pclose);
  hsize_t points = 1;
  for (hsize_t d : dims) points *= d;
  if (options.compress && points > 0) {
    if (state_ && state_->collective) {
      throw Hdf5Error(fmt::format(
          "HDF5: {} cannot be compressed when several MPI ranks write it (parallel HDF5 writes "
          "filtered datasets only with collective transfers); write it uncompressed",
          where));
    }
    if (H5Zfilter_avail(H5Z_FILTER_DEFLATE) <= 0) {
      throw Hdf5Error(fmt::format("HDF5: this HDF5 library has no deflate filter ({})", where));
    }
    // Chunks of about chunk_points points: whole rows of a 2-D dataset where they fit.
    std::vector<hsize_t> chunk(dims.size());
    const hsize_t per_chunk = std::max<hsize_t>(1, options.chunk_points);
    chunk.back() = std::min(dims.back(), per_chunk);
    if (dims.size() == 2) chunk[0] = std::clamp<hsize_t>(per_chunk / chunk[1], 1, dims[0]);
    check_status(H5Pset_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data()),
                 where,
                 "setting the chunk size");
    check_status(H5Pset_shuffle(dcpl.get()), where, "setting the shuffle filter");
    check_status(H5Pset_deflate(dcpl.get(), 4), where, "setting the deflate filter");
  }
  const hid_t id =
      create_described(name,
                       memory_type,  // the file type of every flexure dataset (write_numeric)
                       space.get(),
                       dcpl.get(),
                       units,
                       description);
  Hdf5Dataset dataset(id, memory_type, dims, where);
  dataset.collective_ = state_ && state_->collective;
  return dataset;
}

Hdf5Dataset::Hdf5Dataset(hid_t id, hid_t memory_type, std::vector<hsize_t> dims, std::string where)
    : id_(id), memory_type_(memory_type), dims_(std::move(dims)), where_(std::move(where)) {}

Hdf5Dataset::Hdf5Dataset(Hdf5Dataset&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)),
      memory_type_(other.memory_type_),
      dims_(std::move(other.dims_)),
      where_(std::move(other.where_)),
      collective_(other.collective_) {}

Hdf5Dataset& Hdf5Dataset::operator=(Hdf5Dataset&& other) noexcept {
  if (this != &other) {
    if (id_ >= 0 && H5Iis_valid(id_) > 0) H5Dclose(id_);
    id_ = std::exchange(other.id_, H5I_INVALID_HID);
    memory_type_ = other.memory_type_;
    dims_ = std::move(other.dims_);
    where_ = std::move(other.where_);
    collective_ = other.collective_;
  }
  return *this;
}

Hdf5Dataset::~Hdf5Dataset() {
  if (leave_open_while_unwinding(collective_)) return;
  if (id_ >= 0 && H5Iis_valid(id_) > 0) H5Dclose(id_);
}

hsize_t Hdf5Dataset::size() const {
  hsize_t n = 1;
  for (hsize_t d : dims_) n *= d;
  return n;
}

void Hdf5Dataset::write_range(hsize_t begin, std::span<const double> values) {
  if (memory_type_ != H5T_NATIVE_DOUBLE) {
    throw Hdf5Error(fmt::format("HDF5: {} holds integers, not doubles", where_));
  }
  write_range(begin, values.size(), H5T_NATIVE_DOUBLE, values.data());
}

void Hdf5Dataset::write_range(hsize_t begin, std::span<const int> values) {
  if (memory_type_ != H5T_NATIVE_INT) {
    throw Hdf5Error(fmt::format("HDF5: {} holds doubles, not integers", where_));
  }
  write_range(begin, values.size(), H5T_NATIVE_INT, values.data());
}

void Hdf5Dataset::write_range(hsize_t begin, hsize_t count, hid_t memory_type, const void* data) {
  if (count == 0) return;
  if (begin + count > size()) {
    throw Hdf5Error(fmt::format("HDF5: writing points [{}, {}) past the end ({}) of {}",
                                begin,
                                begin + count,
                                size(),
                                where_));
  }
  ScopedId file_space(check_id(H5Dget_space(id_), where_, "getting the dataspace"), H5Sclose);
  // A row-major range of an N-d dataset as a union of blocks (e.g. in 2-d: the rest of its first
  // row, whole rows, the start of its last row). Each block starts at the range's next point and
  // is the largest one aligned there: whole trailing axes, several steps of one axis, within that
  // axis's extent. HDF5 transfers a union of blocks in row-major order, the range's order.
  const std::size_t rank = dims_.size();
  std::vector<hsize_t> stride(rank, 1);
  for (std::size_t k = rank - 1; k > 0; --k) stride[k - 1] = stride[k] * dims_[k];
  H5S_seloper_t op = H5S_SELECT_SET;
  for (hsize_t at = begin, end = begin + count; at < end;) {
    std::size_t axis = rank - 1;
    for (std::size_t k = 0; k < rank; ++k) {
      if (at % stride[k] == 0 && at + stride[k] <= end) {
        axis = k;
        break;
      }
    }
    std::vector<hsize_t> start(rank), block(rank, 1);
    for (std::size_t k = 0; k < rank; ++k) start[k] = (at / stride[k]) % dims_[k];
    block[axis] = std::min((end - at) / stride[axis], dims_[axis] - start[axis]);
    for (std::size_t k = axis + 1; k < rank; ++k) block[k] = dims_[k];
    check_status(
        H5Sselect_hyperslab(file_space.get(), op, start.data(), nullptr, block.data(), nullptr),
        where_,
        "selecting the range");
    op = H5S_SELECT_OR;
    at += block[axis] * stride[axis];
  }
  ScopedId memory_space(
      check_id(H5Screate_simple(1, &count, nullptr), where_, "creating the memory dataspace"),
      H5Sclose);
  check_status(H5Dwrite(id_, memory_type, memory_space.get(), file_space.get(), H5P_DEFAULT, data),
               where_,
               "writing the range");
}

template <typename T>
void Hdf5Group::write_numeric(const std::string& name,
                              std::span<const T> values,
                              const std::vector<hsize_t>& dims,
                              hid_t type,
                              const std::string& units,
                              const std::string& description) {
  const std::string where = fmt::format("dataset '{}' in {}", child_path(name), file_path_);
  hsize_t size = 1;
  for (hsize_t d : dims) size *= d;
  if (dims.empty() || size != values.size()) {
    throw Hdf5Error(
        fmt::format("HDF5: {} has {} values, which do not fill its shape", where, values.size()));
  }
  ScopedId space(check_id(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                          where,
                          "creating the dataspace"),
                 H5Sclose);
  write_described(name, type, space.get(), size > 0 ? values.data() : nullptr, units, description);
}

void Hdf5Group::write_dataset(const std::string& name,
                              std::span<const double> values,
                              const std::string& units,
                              const std::string& description) {
  write_numeric(name, values, {values.size()}, H5T_NATIVE_DOUBLE, units, description);
}

void Hdf5Group::write_dataset(const std::string& name,
                              std::span<const int> values,
                              const std::string& units,
                              const std::string& description) {
  write_numeric(name, values, {values.size()}, H5T_NATIVE_INT, units, description);
}

void Hdf5Group::write_dataset(const std::string& name,
                              std::span<const double> values,
                              const std::vector<hsize_t>& dims,
                              const std::string& units,
                              const std::string& description) {
  write_numeric(name, values, dims, H5T_NATIVE_DOUBLE, units, description);
}

void Hdf5Group::write_dataset(const std::string& name,
                              std::span<const int> values,
                              const std::vector<hsize_t>& dims,
                              const std::string& units,
                              const std::string& description) {
  write_numeric(name, values, dims, H5T_NATIVE_INT, units, description);
}

void Hdf5Group::write_dataset(const std::string& name,
                              const std::vector<std::string>& values,
                              const std::string& units,
                              const std::string& description) {
  const std::string where = fmt::format("dataset '{}' in {}", child_path(name), file_path_);
  if (state_ && state_->collective) {
    // Parallel HDF5 does not write variable-length data: rank 0 writes it in commit().
    if (units.empty() || description.empty() || description.find('\n') != std::string::npos) {
      throw Hdf5Error(fmt::format("HDF5: {} needs units and a one-line description", where));
    }
    state_->deferred.push_back({group_path_, name, units, description, values});
    return;
  }
  std::vector<const char*> pointers;
  pointers.reserve(values.size());
  for (const std::string& value : values) pointers.push_back(value.c_str());
  ScopedId type(make_string_type(where), H5Tclose);
  const hsize_t size = values.size();
  ScopedId space(check_id(H5Screate_simple(1, &size, nullptr), where, "creating the dataspace"),
                 H5Sclose);
  write_described(
      name, type.get(), space.get(), size > 0 ? pointers.data() : nullptr, units, description);
}

void Hdf5Group::write_scalar(const std::string& name,
                             double value,
                             const std::string& units,
                             const std::string& description) {
  const std::string where = fmt::format("dataset '{}' in {}", child_path(name), file_path_);
  ScopedId space(check_id(H5Screate(H5S_SCALAR), where, "creating the dataspace"), H5Sclose);
  write_described(name, H5T_NATIVE_DOUBLE, space.get(), &value, units, description);
}

void Hdf5Group::set_scalar_attribute(const std::string& name, hid_t type, const void* value) {
  const std::string where = fmt::format("attribute '{}' of {}", name, this->where());
  ScopedId space(check_id(H5Screate(H5S_SCALAR), where, "creating the dataspace"), H5Sclose);
  ScopedId attribute(
      check_id(H5Acreate2(id_, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
               where,
               "creating the attribute"),
      H5Aclose);
  check_status(H5Awrite(attribute.get(), type, value), where, "writing the attribute");
}

void Hdf5Group::set_attribute(const std::string& name, const std::string& value) {
  write_string_attribute(
      id_, name, value, fmt::format("attribute '{}' of {}", name, this->where()));
}

void Hdf5Group::set_attribute(const std::string& name, const char* value) {
  set_attribute(name, std::string(value));
}

void Hdf5Group::set_attribute(const std::string& name, double value) {
  set_scalar_attribute(name, H5T_NATIVE_DOUBLE, &value);
}

void Hdf5Group::set_attribute(const std::string& name, std::int64_t value) {
  set_scalar_attribute(name, H5T_NATIVE_INT64, &value);
}

// ---------------------------------------------------------------------------------------------
// AtomicHdf5File

AtomicHdf5File::AtomicHdf5File(std::string path, Hdf5Access access)
    : path_(std::move(path)), root_(H5I_INVALID_HID, path_, "/") {
  disable_hdf5_error_printing();
  if (path_.empty()) throw Hdf5Error("cannot write an HDF5 file to an empty path");
  const std::string problem = output_path_problem(path_);
  if (!problem.empty()) {
    throw Hdf5Error(fmt::format("cannot write HDF5 file '{}': {}", path_, problem));
  }
  state_ = std::make_shared<detail::Hdf5FileState>();
  const parallel::World* world = nullptr;
  if (access == Hdf5Access::kCollective && parallel::world().parallel()) {
    world = &parallel::world();
    state_->collective = true;
    state_->writes_whole = world->root();
  }

  // Same directory as the target so that rename() is atomic (same file system). The name is
  // unique per process and call; H5F_ACC_EXCL refuses to clobber anything. It is cut to fit the
  // file-name limit, so that any target name the file system allows can be written. A collective
  // file takes rank 0's name.
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path target(path_);
  const std::string directory =
      target.parent_path().empty() ? std::string(".") : target.parent_path().string();
  if (world == nullptr || world->root()) {
    // The temporaries of runs killed without their handlers (kill -9 of mpirun takes every rank
    // down at once): removed when their process is gone (output_path.h).
    remove_stale_temporaries(path_);
    temp_path_ = temporary_path_for(path_,
                                    static_cast<long>(::getpid()),
                                    counter.fetch_add(1),
                                    file_name_limit(directory),
                                    temporary_host_tag());
  }
  if (world != nullptr) temp_path_ = world->broadcast(temp_path_);

  ScopedId access_list(
      check_id(H5Pcreate(H5P_FILE_ACCESS), path_, "creating file-access properties"), H5Pclose);
  // STRONG: closing the file closes every group or dataset still open, so commit() really has
  // the complete file on disk before the rename.
  check_status(
      H5Pset_fclose_degree(access_list.get(), H5F_CLOSE_STRONG), path_, "setting close degree");
#ifdef FLEXURE_WITH_MPI
  if (world != nullptr) {
    check_status(H5Pset_fapl_mpio(access_list.get(), MPI_COMM_WORLD, MPI_INFO_NULL),
                 path_,
                 "selecting the MPI-IO driver");
  }
#endif
  // Registered before it exists: a signal in between finds nothing to unlink, which is harmless.
  // Every rank of a collective file registers it: mpirun stops the others with SIGTERM when one
  // fails, and whichever handler runs first removes it.
  cleanup_slot_ = register_temp_file(temp_path_);
  errno = 0;
  file_ = H5Fcreate(temp_path_.c_str(), H5F_ACC_EXCL, H5P_DEFAULT, access_list.get());
  if (file_ < 0) {
    // HDF5 does not say why; the errno of the failed open() is usually still there.
    const std::string reason = errno != 0 ? std::strerror(errno) : "HDF5 gave no reason";
    unregister_temp_file(cleanup_slot_);
    cleanup_slot_ = -1;
    throw Hdf5Error(
        fmt::format("cannot write HDF5 file '{}': creating the temporary file '{}' "
                    "next to it failed ({})",
                    path_,
                    temp_path_,
                    reason));
  }
  hid_t root = H5Gopen2(file_, "/", H5P_DEFAULT);
  if (root < 0) {
    discard();
    throw Hdf5Error(fmt::format("HDF5: opening the root group of '{}' failed", temp_path_));
  }
  root_ = Hdf5Group(root, path_, "/", state_);
}

AtomicHdf5File::~AtomicHdf5File() {
  if (!committed_) discard();
}

void AtomicHdf5File::discard() noexcept {
  // A collective file is only removed: closing it is collective, and this rank may be the only
  // one failing (the run then ends with MPI_Abort; parallel/mpi_world.h RankFailure).
  const bool collective = state_ && state_->collective;
  if (!collective) {
    if (root_.id_ >= 0 && H5Iis_valid(root_.id_) > 0) H5Gclose(root_.id_);
    root_.id_ = H5I_INVALID_HID;
    if (file_ >= 0) H5Fclose(file_);
    file_ = H5I_INVALID_HID;
  }
  if (!temp_path_.empty()) std::remove(temp_path_.c_str());
  unregister_temp_file(cleanup_slot_);
  cleanup_slot_ = -1;
}

void AtomicHdf5File::commit() {
  if (committed_) throw Hdf5Error(fmt::format("HDF5 file '{}' was already committed", path_));
  // A file that does not say where it came from is a bug in its writer, refused like a failed
  // write (the temporary is removed; the target is left as it was).
  for (const std::string& name : provenance_attribute_names()) {
    if (root_.id_ < 0 || H5Aexists(root_.id_, name.c_str()) <= 0) {
      discard();
      throw Hdf5Error(
          fmt::format("HDF5 file '{}' lacks the root attribute '{}': its writer did not call "
                      "io::write_provenance (docs/hdf5-schema.md)",
                      path_,
                      name));
    }
  }
  if (root_.id_ >= 0) H5Gclose(root_.id_);
  root_.id_ = H5I_INVALID_HID;
  const herr_t closed = H5Fclose(file_);  // collective for a collective file
  file_ = H5I_INVALID_HID;
  const bool collective = state_ && state_->collective;
  std::string failure;
  if (closed < 0) failure = fmt::format("HDF5: closing (flushing) '{}' failed", temp_path_);
  if (collective) {
    // Rank 0 finishes the file; every rank learns the outcome, so that all go on or all fail.
    if (!parallel::world().all(closed >= 0)) failure = "HDF5: closing the collective file failed";
    if (failure.empty() && parallel::world().root()) {
      try {
        write_deferred_strings();
      } catch (const Hdf5Error& e) {
        failure = e.what();
      }
    }
  }
  if (failure.empty() && (!collective || parallel::world().root()) &&
      std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    failure =
        fmt::format("cannot rename '{}' to '{}': {}", temp_path_, path_, std::strerror(errno));
  }
  if (collective) failure = parallel::world().broadcast(failure);
  if (!failure.empty()) {
    state_->collective = false;  // closed: discard() only removes the temporary
    discard();
    throw Hdf5Error(failure);
  }
  // After the rename: a signal before it still removes the temporary.
  unregister_temp_file(cleanup_slot_);
  cleanup_slot_ = -1;
  committed_ = true;
}

// The string datasets that a collective file deferred (rank 0, after every rank closed the file).
void AtomicHdf5File::write_deferred_strings() {
  if (state_->deferred.empty()) return;
  ScopedId file(check_id(H5Fopen(temp_path_.c_str(), H5F_ACC_RDWR, H5P_DEFAULT),
                         path_,
                         "reopening the file for its string datasets"),
                H5Fclose);
  for (const detail::Hdf5FileState::DeferredStrings& d : state_->deferred) {
    hid_t id =
        check_id(H5Gopen2(file.get(), d.group_path.c_str(), H5P_DEFAULT), path_, "opening a group");
    Hdf5Group group(id, path_, d.group_path);
    group.write_dataset(d.name, d.values, d.units, d.description);
  }
  check_status(H5Fclose(file.release()), path_, "closing the file after its string datasets");
}

}  // namespace flexure::io
