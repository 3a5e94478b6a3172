#pragma once
// Where an HDF5 file came from, written on its root by every writer (docs/hdf5-schema.md "Every
// file"), so that a file can be understood and reproduced without the source:
//
//   tool             "flexure"
//   tool_version     flexure/version.h kVersion (what `flexure --version` prints)
//   git_commit       the commit the tool was built from
//   command_line     the full command line, each argument shell-quoted where needed
//   creation_time    UTC, ISO 8601 ("2025-01-31T12:00:00Z")
//   status_meanings  one line per code of every integer code dataset in the file:
//                    "<dataset> <code>: <meaning>" (empty when the file has none)
//
// AtomicHdf5File::commit() refuses a file whose root lacks one of these attributes.
#include <string>
#include <vector>

#include "flexure/io/platform/hdf5_file.h"

namespace flexure::io {

// The meaning of one value of an integer code dataset (`status`, `within_validity`, ...).
struct CodeMeaning {
  std::string dataset;  // the dataset's name (the same name in every group that has it)
  int code = 0;
  std::string meaning;  // one line
};

// Records the command line of this process, for every file written afterwards (main() calls it
// once). Without it, command_line() reads /proc/self/cmdline.
void record_command_line(int argc, const char* const* argv);

// While one exists on this thread, the files it writes record `arguments` as their command line
// (a command run in-process by the Python module, cli/command_runner.h). Nests.
class CommandLineScope {
 public:
  explicit CommandLineScope(std::vector<std::string> arguments);
  ~CommandLineScope();
  CommandLineScope(const CommandLineScope&) = delete;
  CommandLineScope& operator=(const CommandLineScope&) = delete;

 private:
  std::vector<std::string> arguments_;
  const std::vector<std::string>* previous_;
};

// The recorded command line (or /proc/self/cmdline; "unknown" when neither is available), every
// argument passed through shell_quote and joined by single spaces.
std::string command_line();

// `argument` as a POSIX shell reads it back: unchanged when it holds only characters the shell
// leaves alone (letters, digits, @%+=:,./_-), else in single quotes ('' for an empty argument).
std::string shell_quote(const std::string& argument);

// The current UTC time, ISO 8601 to the second, e.g. "2025-01-31T12:00:00Z".
std::string utc_now_iso8601();

// The root attribute names listed above, in that order.
const std::vector<std::string>& provenance_attribute_names();

// Writes the attributes listed above on `root` (the file's root group). `codes` lists every code
// that a dataset of the file may hold; status_meanings is formatted from it.
void write_provenance(Hdf5Group& root, const std::vector<CodeMeaning>& codes);

}  // namespace flexure::io
