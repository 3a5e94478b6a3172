#pragma once
// The tool under `mpirun` (docs/scaling.md): which commands divide their work over the ranks,
// and what the other ranks print.
namespace flexure::cli {

// Throws InvalidInput when mpirun started several copies of a command that does not divide its
// work (each copy would run it whole), or of a tool built without MPI. The commands that do:
// sweep beam, map cfm, design cfm --all-subclasses, mechanism validate, mechanism tolerance.
void check_mpi_launch(int argc, char** argv);

// Ranks other than 0 print nothing on stdout (rank 0 prints the run's report); their stderr stays
// for a failure of their own. restore_stdout() undoes it (a rank reporting its own failure with
// --json).
void silence_stdout_of_other_ranks();
void restore_stdout();

// Rank 0 of an MPI run: one line on stderr with the items each rank computed (the balance of the
// dynamic distribution, io/platform/work_distribution.h); nothing in a run of one rank.
void report_balance();

}  // namespace flexure::cli
