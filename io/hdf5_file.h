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
#include <hdf5.h>

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace flexure::io {

class Hdf5Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Switches off HDF5's automatic error stack printing (process-wide, once). Called by every
// constructor below; errors are reported as exceptions instead.
void disable_hdf5_error_printing();

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

  // 1-D datasets written in one call (contiguous layout, native little-endian types).
  void write_dataset(const std::string& name, std::span<const double> values);
  void write_dataset(const std::string& name, std::span<const int> values);
  // Variable-length UTF-8 strings (e.g. problem or method names in a results table).
  void write_dataset(const std::string& name, const std::vector<std::string>& values);

  // Scalar attributes on this group (on the root group they are file attributes).
  void set_attribute(const std::string& name, const std::string& value);
  void set_attribute(const std::string& name, const char* value);
  void set_attribute(const std::string& name, double value);
  void set_attribute(const std::string& name, std::int64_t value);

  // "file.h5:/group" for messages.
  std::string where() const;
  hid_t id() const { return id_; }

 private:
  friend class AtomicHdf5File;
  Hdf5Group(hid_t id, std::string file_path, std::string group_path);
  template <typename T>
  void write_numeric(const std::string& name, std::span<const T> values, hid_t type);
  void set_scalar_attribute(const std::string& name, hid_t type, const void* value);
  std::string child_path(const std::string& name) const;

  hid_t id_ = H5I_INVALID_HID;
  std::string file_path_;   // the target path (not the temporary), for messages
  std::string group_path_;  // "/" or "/a/b"
};

// An HDF5 file written under a temporary name and renamed to `path` on commit().
class AtomicHdf5File {
 public:
  // Creates the temporary file next to `path`. Throws Hdf5Error naming `path` and the reason if
  // it cannot be written and renamed into place (io/output_path.h: missing or read-only
  // directory, a name over the file-name limit, a directory or device in its place, a file of
  // another user in a sticky directory), before any work is done.
  explicit AtomicHdf5File(std::string path);
  AtomicHdf5File(const AtomicHdf5File&) = delete;
  AtomicHdf5File& operator=(const AtomicHdf5File&) = delete;
  // Without commit(): closes and removes the temporary file; the target is left untouched.
  ~AtomicHdf5File();

  Hdf5Group& root() { return root_; }

  // Closes the file (closing every group still open) and renames it over `path`. Throws
  // Hdf5Error and removes the temporary if closing or renaming fails. Call at most once.
  void commit();

  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_path_; }
  bool committed() const { return committed_; }

 private:
  void discard() noexcept;

  std::string path_;
  std::string temp_path_;
  hid_t file_ = H5I_INVALID_HID;
  Hdf5Group root_;
  bool committed_ = false;
  int cleanup_slot_ = -1;  // temp_file_cleanup.h: removed if a signal stops the process
};

}  // namespace flexure::io
