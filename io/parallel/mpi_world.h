#pragma once
// The ranks of an `mpirun` run (docs/scaling.md). In a build with FLEXURE_MPI=ON started by
// mpirun, world() initialises MPI on first use and reports this process's rank among the size;
// everywhere else (the serial build, or the MPI build started without mpirun) it reports rank 0
// of 1 and never touches MPI, so that the tool behaves exactly as the serial one.
//
// Only the calling thread of main() calls MPI (MPI_THREAD_FUNNELED): the work distribution
// (work_distribution.h) computes on other threads but communicates and writes on this one.
//
// The collectives below are no-ops (returning the local value) in a run of one rank. Every rank
// must call them in the same order, as with MPI itself.
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

namespace flexure::parallel {

// True in a build with FLEXURE_MPI=ON.
bool mpi_build();

// The rank and size that the launcher (mpirun) gave this process, read from its environment
// without initialising MPI (Open MPI's OMPI_COMM_WORLD_*, PMIx, PMI); 0 and 1 without one.
int launched_rank();
int launched_size();

class World {
 public:
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool parallel() const { return size_ > 1; }
  bool root() const { return rank_ == 0; }

  void barrier() const;
  // A barrier that gives up after `seconds`: whether every rank arrived in time (a run's ranks
  // agreeing to end on an error they all met; one that did not gets MPI_Abort instead of a hang).
  bool barrier_within(double seconds) const;
  std::int64_t sum(std::int64_t local) const;
  std::int64_t min(std::int64_t local) const;
  // Logical and of `local` over the ranks: whether every rank succeeded.
  bool all(bool local) const;
  // Rank `from`'s value on every rank.
  std::string broadcast(const std::string& value, int from = 0) const;
  std::int64_t broadcast(std::int64_t value, int from = 0) const;
  // Every rank's `local` strings, concatenated on rank 0 in rank order (empty on the others).
  std::vector<std::string> gather(const std::vector<std::string>& local) const;
  std::vector<double> gather(const std::vector<double>& local) const;
  std::vector<std::int64_t> gather(const std::vector<std::int64_t>& local) const;

  // Ends every rank of the run at once (MPI_Abort) with `exit_code`; in a run of one rank,
  // std::exit. Never returns. Callers remove their temporary files first.
  [[noreturn]] void abort(int exit_code) const;

 private:
  friend const World& world();
  int rank_ = 0;
  int size_ = 1;
};

// The run's world; initialises MPI on the first call when started by mpirun in the MPI build
// (MPI_Finalize runs at normal exit). Throws std::runtime_error when the serial build is started
// by mpirun with more than one rank: every rank would run the whole study and write the same file.
const World& world();

// Whether world() has been called (without calling it).
bool world_started();

// Finalises MPI if world() initialised it (at the end of main; also registered with atexit).
void finalize();

// A failure on one rank while the others go on (an exception in an item of the distributed work,
// a write that failed): the run must end with MPI_Abort, not wait for this rank. The message
// names the rank and the item.
// `cause` is the original exception (its type decides the exit code).
class RankFailure : public std::runtime_error {
 public:
  RankFailure(const std::string& message, std::exception_ptr cause)
      : std::runtime_error(message), cause_(std::move(cause)) {}
  const std::exception_ptr& cause() const { return cause_; }

 private:
  std::exception_ptr cause_;
};

}  // namespace flexure::parallel
