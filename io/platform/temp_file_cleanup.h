#pragma once
// Removes registered temporary files when the process is stopped by SIGINT, SIGTERM or SIGHUP, so
// that an interrupted `--out` run leaves neither a partial target (AtomicHdf5File renames only
// complete files) nor a hidden temporary next to it. The handler only calls unlink() on paths
// stored in fixed buffers (async-signal-safe), then re-raises the signal with its default action,
// so the exit status still says which signal stopped the process. It can also print a note saying
// how to continue (set_interrupt_note).
#include <string>

namespace flexure::io {

// Registers `path` for removal on those signals (installs the handlers on first use). Returns a
// slot to pass to unregister_temp_file, or -1 when the registry is full or the path too long (the
// file is then only removed by the normal destructor path).
int register_temp_file(const std::string& path);
// Forgets the slot (after the file was renamed or removed); -1 is ignored.
void unregister_temp_file(int slot);

// Installs the handlers without registering a file (they also write the blocks in progress of an
// MPI run, parallel/work_distribution.h). Idempotent.
void install_interrupt_handlers();

// Removes every registered temporary file now and forgets it (a process about to end without
// running destructors: an MPI rank calling MPI_Abort, parallel/mpi_world.h).
void remove_temp_files();

// A note for the user, written to stderr by the same handler (write(2), after removing the
// temporaries, before the default action): `note`, or `note_if_missing` when `file` is given and
// does not exist at that moment (access(2); both calls are async-signal-safe). For a run that can
// be continued, e.g. `flexure bench` naming its checkpoint and the command to resume. Installs the
// handlers; an empty `note` clears it. Notes longer than 8 KiB are cut.
void set_interrupt_note(const std::string& note,
                        const std::string& file = {},
                        const std::string& note_if_missing = {});

}  // namespace flexure::io
