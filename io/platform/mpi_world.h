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
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace flexure::parallel {

// True in a build with FLEXURE_MPI=ON.
bool mpi_build();

// The rank and size that the launcher (mpirun) gave this process, read from its environment
// without initialising MPI (Open MPI's OMPI_COMM_WORLD_*, PMIx with Slurm's
// SLURM_STEP_NUM_TASKS, PMI); 0 and 1 without one.
int launched_rank();
int launched_size();

class World {
 public:
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool parallel() const { return size_ > 1; }
  bool root() const { return rank_ == 0; }

  void barrier() const;
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
  // std::exit. Never returns. Removes this process's registered temporary files first
  // (io/platform/temp_file_cleanup.h): no destructor runs after MPI_Abort.
  [[noreturn]] void abort(int exit_code) const;

  // The largest of every rank's `code`, and rank 0's own, once every rank has called it; nullopt
  // when not every rank arrived within `seconds` (negative: no limit). The ranks of a run agree
  // on its exit code with it at the end, so that an error one rank met ends the others too
  // (cli/cli_common.cpp run_app).
  struct AgreedCode {
    int largest = 0;
    int root = 0;
  };
  std::optional<AgreedCode> agree(int code, double seconds) const;

 private:
  friend const World& world();
  int rank_ = 0;
  int size_ = 1;
};

// The run's world; initialises MPI on the first call when started by mpirun in the MPI build
// (MPI_Finalize runs at normal exit). Throws std::runtime_error when the serial build is started
// by mpirun with more than one rank: every rank would run the whole study and write the same file.
const World& world();

// Whether world() has been called and started (without calling it).
bool world_started();

// Finalises HDF5, then MPI, if world() initialised MPI (registered with atexit).
void finalize();

class RankFailure;

// What a rank does on a RankFailure before it is thrown (null: nothing; the exception is thrown).
// The tool sets one that reports the failure and ends the run with World::abort: without
// unwinding, because closing this rank's share of a collective HDF5 file is a collective call
// that the other ranks, still computing, do not join.
void set_rank_failure_handler(std::function<void(const RankFailure&)> handler);
void handle_rank_failure(const RankFailure& failure);

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
