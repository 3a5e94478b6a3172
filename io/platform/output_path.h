#pragma once
// Checks that an output file can be written where the user asked, before any work is done.
//
// flexure writes every output file whole or not at all (io/platform/hdf5_file.h): a temporary file
// is created next to the target and renamed over it when complete. Everything that can make the
// creation or the rename fail is checked here, so that a command taking --out fails in milliseconds
// (exit 2) instead of after a sweep of many minutes: the name's length, the directory, what the
// target is now (a directory, a device or FIFO, which rename() would replace), and the
// sticky-directory rule that only the owner of a file (or of the directory) may replace it.
#include <string>
#include <vector>

namespace flexure::io {

// Why a file cannot be written and renamed to `path`, in words a user can act on, or "" if it
// can (as far as can be known without writing). Used by AtomicHdf5File as well.
std::string output_path_problem(const std::string& path);

// Throws InvalidInput "OPTION PATH: reason" (exit 2) if output_path_problem(path) is not empty.
// Every command that takes --out calls it before solving.
void check_output_path(const std::string& path, const std::string& option = "--out");

// The temporary file AtomicHdf5File writes for `target`: ".NAME.PID-SERIAL@HOST.tmp" in the
// target's directory, where NAME is the target's file name cut (at a UTF-8 character boundary) so
// that the whole fits the file system's file-name limit `name_max` (NAME_MAX, 255 bytes on Linux):
// any target name that fits the limit itself can be written. PID is the writing process, HOST
// (temporary_host_tag()) the machine it runs on, so that a later run can tell a temporary whose
// process is gone (remove_stale_temporaries). Without a host: ".NAME.PID-SERIAL.tmp", the name
// before hosts were recorded.
std::string temporary_path_for(const std::string& target,
                               long pid,
                               unsigned serial,
                               long name_max,
                               const std::string& host = {});

// This machine's host name as it appears in temporary names: up to its first '.', only letters,
// digits, '-' and '_', at most 32 bytes ("localhost" when it has none).
std::string temporary_host_tag();

// Removes the temporaries that flexure processes left next to `target` when they were killed
// without running their handlers (kill -9 of the process, or of mpirun, which takes its ranks
// down at once; docs/scaling.md "Failures"): in the target's directory, every
// ".NAME.PID-SERIAL@HOST.tmp" of this host whose process PID no longer exists (or has ended and
// waits to be reaped: a zombie), or is a younger process that reuses the number (it started after
// the file was last written), and the same for the host-less names of this target. Temporaries of
// other hosts (a shared file system) and of live processes are left alone. Returns the paths
// removed. Errors are ignored (a file that cannot be removed stays).
std::vector<std::string> remove_stale_temporaries(const std::string& target);

// Writes `text` to `path` whole or not at all: into a temporary file next to it (removed on
// SIGINT/SIGTERM/SIGHUP, temp_file_cleanup.h), flushed, then renamed over the target. Throws
// InvalidInput "OPTION PATH: reason" when the path cannot be written (check_output_path) or the
// write fails; the target is then unchanged.
void write_text_file(const std::string& path,
                     const std::string& text,
                     const std::string& option = "--out");

// The file-name limit of the file system holding `directory` (pathconf _PC_NAME_MAX), or NAME_MAX
// when it cannot be asked.
long file_name_limit(const std::string& directory);

}  // namespace flexure::io
