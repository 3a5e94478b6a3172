#include "flexure/io/parallel/work_distribution.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <future>
#include <thread>
#include <vector>

#include "flexure/io/parallel/mpi_world.h"

#ifdef FLEXURE_WITH_MPI
#include <mpi.h>
#endif

namespace flexure::parallel {
namespace {

// Blocks in progress per rank, for write_blocks_in_progress (rank 0; the first kTracked ranks).
constexpr int kTracked = 256;
struct InFlight {
  std::atomic<long> begin{-1};
  std::atomic<long> end{-1};
};
std::array<InFlight, kTracked> in_flight;
std::atomic<bool> tracking{false};

std::vector<long> balance;  // items_per_rank()

void track(int rank, long begin, long end) {
  if (rank < 0 || rank >= kTracked) return;
  in_flight[rank].begin.store(begin, std::memory_order_relaxed);
  in_flight[rank].end.store(end, std::memory_order_relaxed);
}

// A share of what is left, at most max_block: big blocks early (little traffic), single items at
// the end (ranks finish together).
long next_block_size(long left, int ranks, long max_block) {
  return std::clamp(left / (4L * ranks), 1L, std::max(1L, max_block));
}

std::string describe_items(long begin, long end, const DistributionOptions& options) {
  std::string text =
      end - begin == 1 ? fmt::format("item {}", begin) : fmt::format("items {}-{}", begin, end - 1);
  if (options.describe) text += fmt::format(" (first: {})", options.describe(begin));
  return text;
}

[[noreturn]] void fail(int rank, long begin, long end, const DistributionOptions& options) {
  const std::exception_ptr cause = std::current_exception();
  std::string what = "unknown error";
  try {
    std::rethrow_exception(cause);
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
  }
  throw RankFailure(
      fmt::format("rank {} failed on {}: {}", rank, describe_items(begin, end, options), what),
      cause);
}

// FLEXURE_FAIL_ITEM=<n> (docs/scaling.md "Testing the failure path"): the block holding item n
// throws, on whichever rank computes it. Read once.
long injected_failure_item() {
  static const long item = [] {
    const char* v = std::getenv("FLEXURE_FAIL_ITEM");
    return v != nullptr && *v != '\0' ? std::strtol(v, nullptr, 10) : -1L;
  }();
  return item;
}

BlockWriter compute_checked(const BlockCompute& compute, long begin, long end) {
  const long injected = injected_failure_item();
  if (injected >= begin && injected < end) {
    throw std::runtime_error(
        fmt::format("injected failure at item {} (FLEXURE_FAIL_ITEM)", injected));
  }
  return compute(begin, end);
}

long run_serial(long total, const BlockCompute& compute, const DistributionOptions& options) {
  long done = 0;
  while (done < total) {
    const long end = std::min(total, done + std::max(1L, options.max_block));
    // One rank: an exception goes out as it is (its message names the item).
    compute_checked(compute, done, end)();
    done = end;
    if (options.progress) options.progress(done, total);
  }
  return total;
}

#ifdef FLEXURE_WITH_MPI
constexpr int kTagRequest = 71;  // worker -> 0: items done so far (int64)
constexpr int kTagAssign = 72;   // 0 -> worker: begin, end (int64[2]); begin < 0: no more

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(fmt::format("MPI: {} failed", what));
}

long run_worker(const World& w,
                long /*total*/,
                const BlockCompute& compute,
                const DistributionOptions& options) {
  long done = 0;
  std::int64_t block[2] = {-1, -1};
  std::int64_t next[2] = {-1, -1};
  std::int64_t report = 0;
  check(MPI_Send(&report, 1, MPI_INT64_T, 0, kTagRequest, MPI_COMM_WORLD), "MPI_Send");
  check(MPI_Recv(block, 2, MPI_INT64_T, 0, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Recv");
  while (block[0] >= 0) {
    // Ask for the next block now: the reply comes while this one is computed.
    report = done;
    check(MPI_Send(&report, 1, MPI_INT64_T, 0, kTagRequest, MPI_COMM_WORLD), "MPI_Send");
    MPI_Request pending = MPI_REQUEST_NULL;
    check(MPI_Irecv(next, 2, MPI_INT64_T, 0, kTagAssign, MPI_COMM_WORLD, &pending), "MPI_Irecv");
    try {
      compute_checked(compute, block[0], block[1])();
    } catch (...) {
      fail(w.rank(), block[0], block[1], options);
    }
    done += block[1] - block[0];
    check(MPI_Wait(&pending, MPI_STATUS_IGNORE), "MPI_Wait");
    block[0] = next[0];
    block[1] = next[1];
  }
  return done;
}

long run_root(const World& w,
              long total,
              const BlockCompute& compute,
              const DistributionOptions& options) {
  long next = 0;                            // first item not handed out
  long own_done = 0;                        // items rank 0 computed and wrote
  std::vector<long> reported(w.size(), 0);  // items each worker reported done
  int workers_left = w.size() - 1;
  bool own_finished = false;
  std::future<BlockWriter> own;
  long own_begin = -1, own_end = -1;
  const auto take = [&]() -> std::pair<long, long> {
    if (next >= total) return {-1, -1};
    const long n = next_block_size(total - next, w.size(), options.max_block);
    const long begin = next;
    next = std::min(total, next + n);
    return {begin, next};
  };
  tracking.store(true);
  for (int r = 0; r < std::min(w.size(), kTracked); ++r) track(r, -1, -1);
  long last_progress = -1;
  while (true) {
    bool busy = false;
    // Answer every waiting request.
    int flag = 1;
    while (flag) {
      MPI_Status status;
      check(MPI_Iprobe(MPI_ANY_SOURCE, kTagRequest, MPI_COMM_WORLD, &flag, &status), "MPI_Iprobe");
      if (!flag) break;
      busy = true;
      std::int64_t report = 0;
      check(MPI_Recv(&report,
                     1,
                     MPI_INT64_T,
                     status.MPI_SOURCE,
                     kTagRequest,
                     MPI_COMM_WORLD,
                     MPI_STATUS_IGNORE),
            "MPI_Recv");
      reported[status.MPI_SOURCE] = static_cast<long>(report);
      const auto [begin, end] = take();
      std::int64_t block[2] = {begin, end};
      if (begin < 0) --workers_left;
      track(status.MPI_SOURCE, begin, end);
      check(MPI_Send(block, 2, MPI_INT64_T, status.MPI_SOURCE, kTagAssign, MPI_COMM_WORLD),
            "MPI_Send");
    }
    // Rank 0's own block: computed on a second thread, written here.
    if (own.valid() && own.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
      busy = true;
      try {
        own.get()();
      } catch (...) {
        fail(0, own_begin, own_end, options);
      }
      own_done += own_end - own_begin;
      track(0, -1, -1);
    }
    if (!own.valid() && !own_finished) {
      const auto [begin, end] = take();
      if (begin < 0) {
        own_finished = true;
      } else {
        own_begin = begin;
        own_end = end;
        track(0, begin, end);
        own = std::async(std::launch::async,
                         [&compute, begin, end] { return compute_checked(compute, begin, end); });
      }
    }
    if (options.progress) {
      long done = own_done;
      for (int r = 1; r < w.size(); ++r) done += reported[r];
      if (done != last_progress) options.progress(done, total);
      last_progress = done;
    }
    if (own_finished && !own.valid() && workers_left == 0) break;
    if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  tracking.store(false);
  return own_done;
}
#endif

void write_text(int fd, const char* text) {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t n = ::write(fd, text, left);
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

// Decimal digits of a non-negative number into buf (async-signal-safe); returns buf.
char* format_long(long value, char* buf, std::size_t size) {
  char* p = buf + size - 1;
  *p = '\0';
  if (value == 0) *--p = '0';
  while (value > 0 && p > buf) {
    *--p = static_cast<char>('0' + value % 10);
    value /= 10;
  }
  return p;
}

}  // namespace

long distribute(long total, const BlockCompute& compute, const DistributionOptions& options) {
  const World& w = world();
  if (total <= 0) return 0;
  if (!w.parallel()) return run_serial(total, compute, options);
#ifdef FLEXURE_WITH_MPI
  const long mine =
      w.root() ? run_root(w, total, compute, options) : run_worker(w, total, compute, options);
  if (options.progress && w.root()) options.progress(total, total);
  const std::vector<std::int64_t> counts = w.gather(std::vector<std::int64_t>{mine});
  balance.resize(counts.size(), 0);
  for (std::size_t r = 0; r < counts.size(); ++r) balance[r] += static_cast<long>(counts[r]);
  return mine;
#else
  return run_serial(total, compute, options);
#endif
}

std::vector<long> items_per_rank() { return balance; }

void write_blocks_in_progress(int fd) {
  if (!tracking.load()) return;
  bool any = false;
  char a[32], b[32], r[32];
  for (int rank = 0; rank < kTracked; ++rank) {
    const long begin = in_flight[rank].begin.load(std::memory_order_relaxed);
    const long end = in_flight[rank].end.load(std::memory_order_relaxed);
    if (begin < 0 || end <= begin) continue;
    write_text(fd, any ? "; " : "flexure: blocks in progress when the run was stopped: ");
    any = true;
    write_text(fd, "rank ");
    write_text(fd, format_long(rank, r, sizeof r));
    write_text(fd, " items ");
    write_text(fd, format_long(begin, a, sizeof a));
    write_text(fd, "-");
    write_text(fd, format_long(end - 1, b, sizeof b));
  }
  if (any) write_text(fd, "\n");
}

}  // namespace flexure::parallel
