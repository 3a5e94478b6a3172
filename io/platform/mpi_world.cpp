#include "flexure/io/platform/mpi_world.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <thread>

#include "flexure/io/platform/temp_file_cleanup.h"

#ifdef FLEXURE_WITH_MPI
#include <hdf5.h>
#include <mpi.h>
#endif

namespace flexure::parallel {
namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  if (v == nullptr || *v == '\0') return fallback;
  char* end = nullptr;
  const long x = std::strtol(v, &end, 10);
  return (end != nullptr && *end == '\0' && x >= 0 && x < (1L << 30)) ? static_cast<int>(x)
                                                                      : fallback;
}

#ifdef FLEXURE_WITH_MPI
bool initialised_here = false;
#endif
std::atomic<bool> started{false};

#ifdef FLEXURE_WITH_MPI
void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(fmt::format("MPI: {} failed", what));
}
#endif

}  // namespace

bool mpi_build() {
#ifdef FLEXURE_WITH_MPI
  return true;
#else
  return false;
#endif
}

int launched_rank() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"}) {
    const int r = env_int(name, -1);
    if (r >= 0) return r;
  }
  return 0;
}

int launched_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    const int n = env_int(name, -1);
    if (n >= 1) return n;
  }
  // Slurm's srun --mpi=pmix sets no size of its own beside PMIx's rank: the step's task count.
  if (env_int("PMIX_RANK", -1) >= 0) {
    const int n = env_int("SLURM_STEP_NUM_TASKS", -1);
    if (n >= 1) return n;
  }
  return 1;
}

const World& world() {
  static World w;
  static std::once_flag once;
  // Set once; thrown by every call, so that a failed start is never tried again (a second
  // MPI_Init is a fatal MPI error that would hide this message).
  static std::string failure;
  std::call_once(once, [] {
    const int launched = launched_size();
#ifdef FLEXURE_WITH_MPI
    // Started by a launcher (mpirun, or srun with PMIx/PMI): MPI gives the true size.
    const bool by_launcher = launched > 1 || std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr ||
                             std::getenv("PMIX_RANK") != nullptr ||
                             std::getenv("PMI_RANK") != nullptr;
    if (by_launcher) {
      int provided = 0;
      if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        failure = "MPI: MPI_Init_thread failed";
        return;
      }
      initialised_here = true;
      std::atexit(finalize);
      // Rank 0 computes on a second thread while its first calls MPI (work_distribution.h).
      if (provided < MPI_THREAD_FUNNELED) {
        failure =
            "MPI: this MPI library gives no MPI_THREAD_FUNNELED support, which the work "
            "distribution needs (docs/scaling.md)";
        return;
      }
      if (MPI_Comm_rank(MPI_COMM_WORLD, &w.rank_) != MPI_SUCCESS ||
          MPI_Comm_size(MPI_COMM_WORLD, &w.size_) != MPI_SUCCESS) {
        w.rank_ = 0;
        w.size_ = 1;
        failure = "MPI: MPI_Comm_rank or MPI_Comm_size failed";
        return;
      }
    }
#else
    if (launched > 1) {
      failure = fmt::format(
          "this flexure was built without MPI (FLEXURE_MPI=OFF), and mpirun started {} copies: "
          "each would run the whole study and write the same file. Build with -DFLEXURE_MPI=ON "
          "(docs/scaling.md) or run it without mpirun",
          launched);
      return;
    }
#endif
    started = true;
  });
  if (!failure.empty()) throw std::runtime_error(failure);
  return w;
}

bool world_started() { return started.load(); }

void finalize() {
#ifdef FLEXURE_WITH_MPI
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (initialised_here && !finalized) {
    // HDF5 closes what is still open at its own exit, which may come after this one: a collective
    // file left open by an error every rank met must be closed while MPI still runs.
    H5close();
    MPI_Finalize();
  }
#endif
}

namespace {
std::function<void(const RankFailure&)> rank_failure_handler;
}  // namespace

void set_rank_failure_handler(std::function<void(const RankFailure&)> handler) {
  rank_failure_handler = std::move(handler);
}

void handle_rank_failure(const RankFailure& failure) {
  if (rank_failure_handler) rank_failure_handler(failure);
}

std::optional<World::AgreedCode> World::agree(int code, double seconds) const {
#ifdef FLEXURE_WITH_MPI
  if (parallel()) {
    // Both values by one maximum: rank 0's code, and INT_MIN from the others. Static: a request
    // that times out stays pending until MPI_Abort, and must not write into a dead stack frame.
    static int local[2];
    static int result[2];
    local[0] = code;
    local[1] = root() ? code : std::numeric_limits<int>::min();
    result[0] = result[1] = code;
    MPI_Request request = MPI_REQUEST_NULL;
    check(MPI_Iallreduce(local, result, 2, MPI_INT, MPI_MAX, MPI_COMM_WORLD, &request),
          "MPI_Iallreduce");
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(std::max(0.0, seconds));
    int done = 0;
    while (MPI_Test(&request, &done, MPI_STATUS_IGNORE) == MPI_SUCCESS && !done) {
      if (seconds >= 0 && std::chrono::steady_clock::now() > deadline) return std::nullopt;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (!done) return std::nullopt;
    return AgreedCode{result[0], result[1]};
  }
#else
  (void)seconds;
#endif
  return AgreedCode{code, code};
}

void World::barrier() const {
#ifdef FLEXURE_WITH_MPI
  if (parallel()) check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");
#endif
}

std::int64_t World::sum(std::int64_t local) const {
#ifdef FLEXURE_WITH_MPI
  if (parallel()) {
    std::int64_t total = 0;
    check(MPI_Allreduce(&local, &total, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
    return total;
  }
#endif
  return local;
}

std::int64_t World::min(std::int64_t local) const {
#ifdef FLEXURE_WITH_MPI
  if (parallel()) {
    std::int64_t least = 0;
    check(MPI_Allreduce(&local, &least, 1, MPI_INT64_T, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
    return least;
  }
#endif
  return local;
}

bool World::all(bool local) const { return min(local ? 1 : 0) == 1; }

std::int64_t World::broadcast(std::int64_t value, int from) const {
#ifdef FLEXURE_WITH_MPI
  if (parallel()) check(MPI_Bcast(&value, 1, MPI_INT64_T, from, MPI_COMM_WORLD), "MPI_Bcast");
#else
  (void)from;
#endif
  return value;
}

std::string World::broadcast(const std::string& value, int from) const {
#ifdef FLEXURE_WITH_MPI
  if (parallel()) {
    std::string out = value;
    const std::int64_t n = broadcast(static_cast<std::int64_t>(value.size()), from);
    out.resize(static_cast<std::size_t>(n));
    check(MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, from, MPI_COMM_WORLD), "MPI_Bcast");
    return out;
  }
#else
  (void)from;
#endif
  return value;
}

namespace {

#ifdef FLEXURE_WITH_MPI
// Gathers `count` elements of `type` from every rank to rank 0 (MPI_Gatherv).
template <typename T>
std::vector<T> gather_raw(const World& w, const std::vector<T>& local, MPI_Datatype type) {
  const int n = static_cast<int>(local.size());
  std::vector<int> counts(w.root() ? w.size() : 0), offsets(counts.size());
  check(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
  std::vector<T> all;
  if (w.root()) {
    int total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
      offsets[r] = total;
      total += counts[r];
    }
    all.resize(static_cast<std::size_t>(total));
  }
  check(MPI_Gatherv(local.data(),
                    n,
                    type,
                    all.data(),
                    counts.data(),
                    offsets.data(),
                    type,
                    0,
                    MPI_COMM_WORLD),
        "MPI_Gatherv");
  return all;
}
#endif

}  // namespace

std::vector<double> World::gather(const std::vector<double>& local) const {
#ifdef FLEXURE_WITH_MPI
  if (parallel()) return gather_raw(*this, local, MPI_DOUBLE);
#endif
  return local;
}

std::vector<std::int64_t> World::gather(const std::vector<std::int64_t>& local) const {
#ifdef FLEXURE_WITH_MPI
  if (parallel()) return gather_raw(*this, local, MPI_INT64_T);
#endif
  return local;
}

std::vector<std::string> World::gather(const std::vector<std::string>& local) const {
#ifdef FLEXURE_WITH_MPI
  if (parallel()) {
    // Lengths, then the characters of all strings joined.
    std::vector<std::int64_t> lengths;
    std::vector<char> joined;
    for (const std::string& s : local) {
      lengths.push_back(static_cast<std::int64_t>(s.size()));
      joined.insert(joined.end(), s.begin(), s.end());
    }
    const std::vector<std::int64_t> all_lengths = gather_raw(*this, lengths, MPI_INT64_T);
    const std::vector<char> all_chars = gather_raw(*this, joined, MPI_CHAR);
    std::vector<std::string> out;
    std::size_t at = 0;
    for (std::int64_t n : all_lengths) {
      out.emplace_back(all_chars.data() + at, static_cast<std::size_t>(n));
      at += static_cast<std::size_t>(n);
    }
    return out;
  }
#endif
  return local;
}

void World::abort(int exit_code) const {
  io::remove_temp_files();
#ifdef FLEXURE_WITH_MPI
  if (parallel()) MPI_Abort(MPI_COMM_WORLD, exit_code);
#endif
  std::exit(exit_code);
}

}  // namespace flexure::parallel
