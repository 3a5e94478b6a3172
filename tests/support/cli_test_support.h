#pragma once
// Helpers for the tests that run the built `flexure` binary (FLEXURE_BINARY): run a command line
// with stdout and stderr captured to files, make scratch directories, read HDF5 data back with the
// plain C API (independently of io/platform/hdf5_file.h).
#include <hdf5.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace flexure::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// A fresh empty directory under the system temp dir, removed by the destructor.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "flexure-test-XXXXXX").string();
    path_ = ::mkdtemp(pattern.data());
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Names of all entries (including hidden temporary files).
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }

 private:
  std::filesystem::path path_;
};

// Runs `FLEXURE_BINARY args` (args are passed through the shell unchanged) in `cwd`. `prefix` is
// put before the binary, e.g. "setpriv --reuid=65534 " to run it as another user.
inline CommandResult run_flexure(const std::string& args,
                                 const std::filesystem::path& cwd = {},
                                 const std::string& prefix = {}) {
  static int serial = 0;
  const auto base = std::filesystem::temp_directory_path() /
                    ("flexure-cli-" + std::to_string(::getpid()) + "-" + std::to_string(serial++));
  const std::string out = base.string() + ".out";
  const std::string err = base.string() + ".err";
  std::string command;
  if (!cwd.empty()) command = "cd '" + cwd.string() + "' && ";
  command += prefix + "'" + FLEXURE_BINARY + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(out);
  result.err = read_text(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return result;
}

// A refusal for the expected reason: `flexure args` exits 2 (invalid input, docs/cli.md) and its
// stderr names the reason with each of `reason` (key words of the message).
inline void expect_refused(const std::string& args,
                           const std::vector<std::string>& reason,
                           const std::filesystem::path& cwd = {}) {
  const CommandResult r = run_flexure(args, cwd);
  EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
  for (const std::string& word : reason) {
    EXPECT_NE(r.err.find(word), std::string::npos) << args << ": '" << word << "' not in " << r.err;
  }
}

// The keys docs/cli.md names for `flexure mechanism analyze --json` (a contract: users' scripts
// read them).
inline const std::vector<std::string>& mechanism_analyze_contract_keys() {
  static const std::vector<std::string> keys = {"displacement",
                                                "force_prbm",
                                                "force_exact",
                                                "percent_constant_force_prbm",
                                                "percent_constant_force_exact",
                                                "max_force_error",
                                                "max_stress",
                                                "safety_factor",
                                                "stability_displacement_control",
                                                "stability_force_control"};
  return keys;
}

// After a failure stdout holds no result: it is empty, or (with --json) exactly one line, the JSON
// error object {"error": ..., "exit_code": the process's exit code, ...}.
inline bool no_result_on_stdout(const CommandResult& r) {
  if (r.out.empty()) return true;
  if (std::count(r.out.begin(), r.out.end(), '\n') != 1) return false;
  const nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  return j.is_object() && j.contains("error") && j.value("exit_code", -1) == r.exit_code;
}

inline int count_lines(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

// --- HDF5 read-back with the C API -------------------------------------------------------------

inline std::vector<double> read_doubles(hid_t file, const char* name) {
  hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
  if (dataset < 0) return {};
  hid_t space = H5Dget_space(dataset);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  std::vector<double> values(static_cast<std::size_t>(count));
  if (count > 0) H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Sclose(space);
  H5Dclose(dataset);
  return values;
}

inline std::vector<int> read_ints(hid_t file, const char* name) {
  hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
  if (dataset < 0) return {};
  hid_t space = H5Dget_space(dataset);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  std::vector<int> values(static_cast<std::size_t>(count));
  if (count > 0) H5Dread(dataset, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Sclose(space);
  H5Dclose(dataset);
  return values;
}

inline std::vector<std::string> read_strings(hid_t file, const char* name) {
  hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
  if (dataset < 0) return {};
  hid_t space = H5Dget_space(dataset);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  std::vector<char*> raw(static_cast<std::size_t>(count), nullptr);
  std::vector<std::string> values;
  if (count > 0 && H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()) >= 0) {
    for (char* s : raw) values.emplace_back(s ? s : "");
    H5Dvlen_reclaim(type, space, H5P_DEFAULT, raw.data());
  }
  H5Tclose(type);
  H5Sclose(space);
  H5Dclose(dataset);
  return values;
}

// Scalar attribute on an object (file root: pass the file id and "/").
inline double read_double_attribute(hid_t file, const char* object, const char* name) {
  double value = 0.0;
  hid_t attribute = H5Aopen_by_name(file, object, name, H5P_DEFAULT, H5P_DEFAULT);
  if (attribute < 0) return std::numeric_limits<double>::quiet_NaN();
  H5Aread(attribute, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attribute);
  return value;
}

inline long long read_int_attribute(hid_t file, const char* object, const char* name) {
  long long value = -1;
  hid_t attribute = H5Aopen_by_name(file, object, name, H5P_DEFAULT, H5P_DEFAULT);
  if (attribute < 0) return -1;
  H5Aread(attribute, H5T_NATIVE_LLONG, &value);
  H5Aclose(attribute);
  return value;
}

inline std::string read_string_attribute(hid_t file, const char* object, const char* name) {
  hid_t attribute = H5Aopen_by_name(file, object, name, H5P_DEFAULT, H5P_DEFAULT);
  if (attribute < 0) return "<missing>";
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  char* raw = nullptr;
  std::string value = "<unreadable>";
  if (H5Aread(attribute, type, &raw) >= 0 && raw != nullptr) {
    value = raw;
    H5free_memory(raw);
  }
  H5Tclose(type);
  H5Aclose(attribute);
  return value;
}

// Opens an HDF5 file read-only with error printing off; returns < 0 when it is not readable.
inline hid_t open_read_only(const std::filesystem::path& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  return H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
}

}  // namespace flexure::test
