#pragma once
// A small C++ wrapper over the HDF5 C API for files that flexure writes (sweeps, validation,
// benchmark results).
//
// Files are written atomically: AtomicHdf5File creates a temporary file in the same directory as
// the target and renames it over the target on commit(), so a reader never sees a half-written
// file and a failed run leaves nothing behind (the destructor removes an uncommitted temporary).
//
// Every HDF5 return value is checked. HDF5's automatic error printing is switched off and failures
// are thrown as Hdf5Error whose message names the file, the object and what failed.
//
// Convention for stored data: NaN in a floating-point dataset means "no solution at this point";
// every file that may contain NaN also carries an integer `status` dataset that flags those points.
//
// Self-describing files (docs/hdf5-schema.md "Every file"): every dataset carries the string
// attributes `units` ("1" dimensionless, "rad", "N", "m", "Pa", "s", ...; "text" for strings) and
// a one-line `description`. There is no write_dataset without them, so a writer cannot forget
// them. The root carries the provenance of io/platform/provenance.h; commit() refuses a file
// without it.
#include <hdf5.h>

#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "flexure/io/platform/hdf5_error.h"

namespace flexure::io {

// Switches off HDF5's automatic error stack printing (process-wide, once). Called by every
// constructor below; errors are reported as exceptions instead.
void disable_hdf5_error_printing();

// Options of a dataset written in parts (Hdf5Group::create_dataset).
struct Hdf5DatasetOptions {
  // Chunked layout with the shuffle filter and deflate (zlib level 4): smaller files of smooth
  // data at some CPU cost. Off: contiguous layout.
  bool compress = false;
  hsize_t chunk_points = 65536;  // points per chunk when compressed
};

// A dataset created whole (its shape, units and description) and filled in parts, in any order,
// e.g. a sweep written chunk by chunk as it is solved so that memory stays flat. Move-only;
// closes its handle when destroyed.
class Hdf5Dataset {
 public:
  Hdf5Dataset(const Hdf5Dataset&) = delete;
  Hdf5Dataset& operator=(const Hdf5Dataset&) = delete;
  Hdf5Dataset(Hdf5Dataset&& other) noexcept;
  Hdf5Dataset& operator=(Hdf5Dataset&& other) noexcept;
  ~Hdf5Dataset();

  // Writes values at the row-major positions [begin, begin + values.size()) of the dataset (any
  // rank: a range of a 2-D dataset may start and end inside rows). The value type must be the
  // dataset's (double for float64, int for int32); throws Hdf5Error otherwise or out of range.
  void write_range(hsize_t begin, std::span<const double> values);
  void write_range(hsize_t begin, std::span<const int> values);
  hsize_t size() const;  // number of points

 private:
  friend class Hdf5Group;
  Hdf5Dataset(hid_t id, hid_t memory_type, std::vector<hsize_t> dims, std::string where);
  void write_range(hsize_t begin, hsize_t count, hid_t memory_type, const void* data);

  hid_t id_ = H5I_INVALID_HID;
  hid_t memory_type_ = H5I_INVALID_HID;  // H5T_NATIVE_DOUBLE or H5T_NATIVE_INT (not owned)
  std::vector<hsize_t> dims_;
  std::string where_;
  bool collective_ = false;  // of a kCollective file under several ranks
};

enum class Hdf5Type { kFloat64, kInt32 };

// How a file is written (docs/scaling.md "One file from many ranks").
//   kSerial:     by this process alone.
//   kCollective: by every rank of parallel::world() together (the MPI build under mpirun; the
//                same as kSerial in a run of one rank). Every rank makes the same calls in the same
//                order with the same arguments (groups, datasets, attributes: HDF5's metadata),
//                except Hdf5Dataset::write_range, which each rank calls for its own ranges. A
//                dataset written whole takes rank 0's values. Parallel HDF5 cannot write
//                variable-length strings, so string datasets are written by rank 0 after the
//                collective part is closed, in commit(). Compression (filters) is refused: parallel
//                HDF5 1.10 writes filtered datasets only with collective transfers.
enum class Hdf5Access { kSerial, kCollective };

namespace detail {
struct Hdf5FileState;
}

// A group (or the root group "/") of a file being written. Move-only; closes its handle when
// destroyed. Must not outlive the file it belongs to.
class Hdf5Group {
 public:
  Hdf5Group(const Hdf5Group&) = delete;
  Hdf5Group& operator=(const Hdf5Group&) = delete;
  Hdf5Group(Hdf5Group&& other) noexcept;
  Hdf5Group& operator=(Hdf5Group&& other) noexcept;
  ~Hdf5Group();

  // Creates a child group; `name` must be a single path component not used yet.
  Hdf5Group create_group(const std::string& name);

  // 1-D datasets written in one call (contiguous layout, native little-endian types), each with
  // its `units` and `description` attributes. Throws Hdf5Error when either is empty or the
  // description spans more than one line.
  void write_dataset(const std::string& name,
                     std::span<const double> values,
                     const std::string& units,
                     const std::string& description);
  void write_dataset(const std::string& name,
                     std::span<const int> values,
                     const std::string& units,
                     const std::string& description);
  // The same shaped as an array of `dims` (row-major, the last index fastest), e.g. a sweep over a
  // grid; the product of dims must equal values.size().
  void write_dataset(const std::string& name,
                     std::span<const double> values,
                     const std::vector<hsize_t>& dims,
                     const std::string& units,
                     const std::string& description);
  void write_dataset(const std::string& name,
                     std::span<const int> values,
                     const std::vector<hsize_t>& dims,
                     const std::string& units,
                     const std::string& description);
  // Variable-length UTF-8 strings (e.g. problem or method names in a results table); units are
  // normally "text".
  void write_dataset(const std::string& name,
                     const std::vector<std::string>& values,
                     const std::string& units,
                     const std::string& description);
  // A dataset of `dims` to be filled in parts with Hdf5Dataset::write_range; with its units and
  // description like every dataset. Points never written read as 0.
  Hdf5Dataset create_dataset(const std::string& name,
                             Hdf5Type type,
                             const std::vector<hsize_t>& dims,
                             const std::string& units,
                             const std::string& description,
                             const Hdf5DatasetOptions& options = {});
  // A scalar (0-d) dataset: one value with units, e.g. a design's Young's modulus.
  void write_scalar(const std::string& name,
                    double value,
                    const std::string& units,
                    const std::string& description);

  // Scalar attributes on this group (on the root group they are file attributes).
  void set_attribute(const std::string& name, const std::string& value);
  void set_attribute(const std::string& name, const char* value);
  void set_attribute(const std::string& name, double value);
  void set_attribute(const std::string& name, std::int64_t value);

  // "file.h5:/group" for messages.
  std::string where() const;
  // Whether several ranks write this group's file (Hdf5Access::kCollective under mpirun).
  bool collective() const;
  hid_t id() const { return id_; }

 private:
  friend class AtomicHdf5File;
  Hdf5Group(hid_t id,
            std::string file_path,
            std::string group_path,
            std::shared_ptr<detail::Hdf5FileState> state = nullptr);
  template <typename T>
  void write_numeric(const std::string& name,
                     std::span<const T> values,
                     const std::vector<hsize_t>& dims,
                     hid_t type,
                     const std::string& units,
                     const std::string& description);
  // Creates dataset `name` of `type` over `space`, writes `data` (may be null for an empty
  // dataset) and its units and description.
  void write_described(const std::string& name,
                       hid_t type,
                       hid_t space,
                       const void* data,
                       const std::string& units,
                       const std::string& description);
  // Creates the dataset with creation properties `dcpl` and its units and description; returns
  // its (open) id.
  hid_t create_described(const std::string& name,
                         hid_t type,
                         hid_t space,
                         hid_t dcpl,
                         const std::string& units,
                         const std::string& description);
  void set_scalar_attribute(const std::string& name, hid_t type, const void* value);
  std::string child_path(const std::string& name) const;

  hid_t id_ = H5I_INVALID_HID;
  std::string file_path_;   // the target path (not the temporary), for messages
  std::string group_path_;  // "/" or "/a/b"
  std::shared_ptr<detail::Hdf5FileState> state_;  // how the file is written (null: serial)
};

// An HDF5 file written under a temporary name and renamed to `path` on commit().
class AtomicHdf5File {
 public:
  // Creates the temporary file next to `path`. Throws Hdf5Error naming `path` and the reason if
  // it cannot be written and renamed into place (io/platform/output_path.h: missing or read-only
  // directory, a name over the file-name limit, a directory or device in its place, a file of
  // another user in a sticky directory), before any work is done.
  //
  // kCollective: every rank calls this with the same path (rank 0 names the temporary file).
  explicit AtomicHdf5File(std::string path, Hdf5Access access = Hdf5Access::kSerial);
  AtomicHdf5File(const AtomicHdf5File&) = delete;
  AtomicHdf5File& operator=(const AtomicHdf5File&) = delete;
  // Without commit(): closes and removes the temporary file; the target is left untouched.
  ~AtomicHdf5File();

  Hdf5Group& root() { return root_; }

  // Closes the file (closing every group still open) and renames it over `path`. Throws
  // Hdf5Error and removes the temporary if the root lacks an attribute of
  // provenance_attribute_names() (io/platform/provenance.h: write_provenance was not called), or if
  // closing or renaming fails. Call at most once. kCollective: every rank calls it; the outcome
  // (rank 0's rename) is the same on every rank.
  void commit();

  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_path_; }
  bool committed() const { return committed_; }

 private:
  void discard() noexcept;
  void write_deferred_strings();

  std::string path_;
  std::string temp_path_;
  hid_t file_ = H5I_INVALID_HID;
  Hdf5Group root_;
  bool committed_ = false;
  std::shared_ptr<detail::Hdf5FileState> state_;
  int cleanup_slot_ = -1;  // temp_file_cleanup.h: removed if a signal stops the process
};

}  // namespace flexure::io
