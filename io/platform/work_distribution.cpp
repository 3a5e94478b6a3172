#include "flexure/io/platform/work_distribution.h"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <future>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/temp_file_cleanup.h"

#ifdef FLEXURE_WITH_MPI
#include <mpi.h>
#endif

namespace flexure::parallel {
namespace {

// Blocks each rank holds, for write_blocks_in_progress (rank 0): the block it computes and the one
// it was given ahead (a rank asks for its next block as it starts one). One entry per rank,
// allocated before tracking starts and kept for the process's life, so that a signal handler
// never reads freed memory.
struct Held {
  std::atomic<long> begin{-1}, end{-1};            // the block being computed
  std::atomic<long> next_begin{-1}, next_end{-1};  // the block handed out ahead of it
};
std::atomic<Held*> held{nullptr};
std::atomic<int> held_count{0};
std::atomic<bool> tracking{false};
std::atomic<bool> blocks_written{false};  // once per distribution (SIGCONT, then SIGTERM)

std::vector<long> balance;  // items_per_rank()

#ifdef FLEXURE_WITH_MPI
// Open MPI's mpirun stops a job (Ctrl-C, a rank that died, MPI_Abort) by sending each rank SIGCONT,
// waiting odls_base_sigkill_timeout (1 s by default), then SIGTERM and SIGKILL a few milliseconds
// later (measured: 2.4 ms). A SIGTERM handler on a loaded machine is not always scheduled in that
// window: the blocks were then never named (about 1 run in 15). The SIGCONT that opens the
// sequence leaves a second: rank 0 names the blocks when the process that started it (mpirun or
// its daemon) sends one. Nothing is removed here: a SIGCONT that resumes a job stopped by job
// control (mpirun forwards those only with orte_forward_job_control set) must not cost the output
// file; the temporary files are removed on SIGTERM as before (io/platform/temp_file_cleanup.cpp).
extern "C" void name_blocks_on_launcher_sigcont(int, siginfo_t* info, void*) {
  if (info == nullptr || info->si_code != SI_USER || info->si_pid != ::getppid()) return;
  const int saved_errno = errno;
  write_blocks_in_progress(STDERR_FILENO);
  errno = saved_errno;
}

void install_sigcont_handler_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction action = {};
    action.sa_sigaction = name_blocks_on_launcher_sigcont;
    action.sa_flags = SA_SIGINFO | SA_RESTART;
    sigemptyset(&action.sa_mask);
    sigaction(SIGCONT, &action, nullptr);
  });
}

void start_tracking(int ranks) {
  if (held_count.load() < ranks) {
    held.store(new Held[static_cast<std::size_t>(ranks)]);  // an older, smaller table is kept
    held_count.store(ranks);
  }
  Held* h = held.load();
  for (int r = 0; r < ranks; ++r) {
    h[r].begin = h[r].end = h[r].next_begin = h[r].next_end = -1;
  }
  blocks_written.store(false);
  tracking.store(true);
  install_sigcont_handler_once();
  // Ctrl-C or mpirun's SIGTERM then names the blocks even where no temporary file was registered
  // (a command without --out).
  io::install_interrupt_handlers();
}

// Rank `rank` was given [begin, end): it computes it now, or after the block it holds.
void track_given(int rank, long begin, long end) {
  Held& h = held.load()[rank];
  if (h.begin.load() < 0) {
    h.begin = begin;
    h.end = end;
  } else {
    h.next_begin = begin;
    h.next_end = end;
  }
}

// Rank `rank` finished the block it was computing; the one given ahead becomes current.
void track_finished(int rank) {
  Held& h = held.load()[rank];
  h.begin = h.next_begin.load();
  h.end = h.next_end.load();
  h.next_begin = h.next_end = -1;
}

// A share of what is left, at most max_block: big blocks early (little traffic), single items at
// the end (ranks finish together).
long next_block_size(long left, int ranks, const DistributionOptions& options) {
  const long most = std::max(1L, options.max_block);
  return std::clamp(left / (4L * ranks), std::clamp(options.min_block, 1L, most), most);
}

std::string describe_items(long begin, long end, const DistributionOptions& options) {
  std::string text =
      end - begin == 1 ? fmt::format("item {}", begin) : fmt::format("items {}-{}", begin, end - 1);
  if (options.describe) {
    try {
      text += fmt::format(" (first: {})", options.describe(begin));
    } catch (...) {  // the failure is reported with the index alone
    }
  }
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
  RankFailure failure(
      fmt::format("rank {} failed on {}: {}", rank, describe_items(begin, end, options), what),
      cause);
  // Ends the run here when the tool has set a handler: unwinding would close this rank's share of
  // a collective file, which the other ranks do not join (mpi_world.h).
  handle_rank_failure(failure);
  throw failure;
}

#endif

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
// Worker -> 0: {kind, items this worker has finished}, all on one tag so that rank 0 receives a
// worker's messages in the order they were sent (MPI's non-overtaking rule).
constexpr int kTagReport = 71;
constexpr int kTagAssign = 72;         // 0 -> worker: begin, end (int64[2]); begin < 0: no more
constexpr std::int64_t kAhead = 1;     // starts a block and asks for the next one
constexpr std::int64_t kFinished = 2;  // finished (and wrote) the block it was computing

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(fmt::format("MPI: {} failed", what));
}

void send_report(std::int64_t kind, long done) {
  const std::int64_t message[2] = {kind, static_cast<std::int64_t>(done)};
  check(MPI_Send(message, 2, MPI_INT64_T, 0, kTagReport, MPI_COMM_WORLD), "MPI_Send");
}

// The first block of every rank, known to all without a message: the first `ranks` blocks in rank
// order (empty pairs when there are fewer blocks than ranks). Each rank starts at once, and none
// can take a second block before every rank has its first: a sweep of cheap loads that rank 0
// could finish before a worker's first request arrives still keeps every rank busy.
std::vector<std::pair<long, long>> first_blocks(long total,
                                                int ranks,
                                                const DistributionOptions& options) {
  std::vector<std::pair<long, long>> blocks(static_cast<std::size_t>(ranks), {-1L, -1L});
  long next = 0;
  for (int r = 0; r < ranks && next < total; ++r) {
    const long n = next_block_size(total - next, ranks, options);
    blocks[static_cast<std::size_t>(r)] = {next, std::min(total, next + n)};
    next = std::min(total, next + n);
  }
  return blocks;
}

long run_worker(const World& w,
                long total,
                const BlockCompute& compute,
                const DistributionOptions& options) {
  long done = 0;
  const std::pair<long, long> first = first_blocks(total, w.size(), options)[w.rank()];
  std::int64_t block[2] = {first.first, first.second};
  std::int64_t next[2] = {-1, -1};
  while (block[0] >= 0) {
    // Ask for the next block now: the reply comes while this one is computed (rank 0 holds it
    // back near the end of the items, until this block is finished: see run_root).
    send_report(kAhead, done);
    MPI_Request pending = MPI_REQUEST_NULL;
    check(MPI_Irecv(next, 2, MPI_INT64_T, 0, kTagAssign, MPI_COMM_WORLD, &pending), "MPI_Irecv");
    try {
      compute_checked(compute, block[0], block[1])();
    } catch (...) {
      // The receive must not outlive `next`: cancel it (or take the reply) before leaving.
      MPI_Cancel(&pending);
      MPI_Wait(&pending, MPI_STATUS_IGNORE);
      fail(w.rank(), block[0], block[1], options);
    }
    done += block[1] - block[0];
    send_report(kFinished, done);
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
  long own_done = 0;                        // items rank 0 computed and wrote
  std::vector<long> reported(w.size(), 0);  // items each worker finished
  std::vector<char> waiting(w.size(), 0);   // a request held back until the worker finishes
  // Every rank's first block is fixed in advance (first_blocks); the rest is handed out on request.
  const std::vector<std::pair<long, long>> firsts = first_blocks(total, w.size(), options);
  long next = 0;  // first item not handed out
  int workers_left = 0;
  for (const auto& [begin, end] : firsts) next = std::max(next, end);
  for (int r = 1; r < w.size(); ++r) workers_left += firsts[r].first >= 0 ? 1 : 0;
  std::pair<long, long> own_first = firsts[0];
  bool own_finished = false;
  std::future<BlockWriter> own;
  long own_begin = -1, own_end = -1;
  const auto take = [&]() -> std::pair<long, long> {
    if (next >= total) return {-1, -1};
    const long n = next_block_size(total - next, w.size(), options);
    const long begin = next;
    next = std::min(total, next + n);
    return {begin, next};
  };
  // A block given ahead waits behind the one the worker computes. Early on that costs nothing and
  // saves the worker a round trip; near the end (fewer than two items per rank left, or items
  // that each cost a block of their own: optimisations, designs) it would leave another rank
  // idle while the item waits, so the request is answered only once the worker is free.
  const auto ahead_allowed = [&] {
    const long left = total - next;
    return options.max_block > 1 &&
           left >= 2L * w.size() * next_block_size(left, w.size(), options);
  };
  const auto assign = [&](int worker) {
    const auto [begin, end] = take();
    const std::int64_t block[2] = {begin, end};
    if (begin < 0) {
      --workers_left;
    } else {
      track_given(worker, begin, end);
    }
    check(MPI_Send(block, 2, MPI_INT64_T, worker, kTagAssign, MPI_COMM_WORLD), "MPI_Send");
  };
  start_tracking(w.size());
  for (int r = 1; r < w.size(); ++r) {
    if (firsts[r].first >= 0) track_given(r, firsts[r].first, firsts[r].second);
  }
  // Clears the table however this ends (a failure of rank 0's own block throws out of the loop).
  struct StopTracking {
    ~StopTracking() { tracking.store(false); }
  } stop_tracking;
  long last_progress = -1;
  while (true) {
    bool busy = false;
    // Every waiting message.
    int flag = 1;
    while (flag) {
      MPI_Status status;
      check(MPI_Iprobe(MPI_ANY_SOURCE, kTagReport, MPI_COMM_WORLD, &flag, &status), "MPI_Iprobe");
      if (!flag) break;
      busy = true;
      const int worker = status.MPI_SOURCE;
      std::int64_t message[2] = {0, 0};
      check(
          MPI_Recv(message, 2, MPI_INT64_T, worker, kTagReport, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
          "MPI_Recv");
      reported[worker] = static_cast<long>(message[1]);
      if (message[0] == kAhead) {
        // With nothing left, "no more" also waits: the worker's last message is then always
        // kFinished, and none is left unreceived when this loop ends.
        if (ahead_allowed() && next < total) {
          assign(worker);
        } else {
          waiting[worker] = 1;
        }
      } else {
        track_finished(worker);
        if (waiting[worker]) {
          waiting[worker] = 0;
          assign(worker);
        }
      }
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
      track_finished(0);
    }
    if (!own.valid() && !own_finished) {
      const auto [begin, end] = own_first.first >= 0 ? own_first : take();
      own_first = {-1, -1};
      if (begin < 0) {
        own_finished = true;
      } else {
        own_begin = begin;
        own_end = end;
        track_given(0, begin, end);
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
  // A minimum block larger than the items allow would leave ranks idle (1000 cheap loads on 2
  // ranks with blocks of at least 1024: one rank computed all): at least two blocks per rank.
  DistributionOptions adapted = options;
  adapted.min_block = std::min(options.min_block, std::max(1L, total / (2L * w.size())));
  const long mine =
      w.root() ? run_root(w, total, compute, adapted) : run_worker(w, total, compute, adapted);
  if (options.progress && w.root()) options.progress(total, total);
  const std::vector<std::int64_t> counts = w.gather(std::vector<std::int64_t>{mine});
  balance.resize(counts.size(), 0);
  for (std::size_t r = 0; r < counts.size(); ++r) balance[r] += static_cast<long>(counts[r]);
  // Every rank leaves together: a worker's first request of a following distribute() must not
  // reach rank 0 while it still answers this one.
  w.barrier();
  return mine;
#else
  return run_serial(total, compute, options);
#endif
}

std::vector<long> items_per_rank() { return balance; }

void write_blocks_in_progress(int fd) {
  if (!tracking.load()) return;
  // Once: on mpirun's SIGCONT and again on its SIGTERM would print the line twice.
  if (blocks_written.exchange(true)) return;
  // The count first: start_tracking publishes a larger table before its count.
  const int ranks = held_count.load();
  const Held* h = held.load();
  if (h == nullptr) return;
  bool any = false;
  char a[32], b[32], r[32];
  const auto write_block = [&](int rank, long begin, long end) {
    if (begin < 0 || end <= begin) return;
    write_text(fd, any ? "; " : "flexure: blocks in progress when the run was stopped: ");
    any = true;
    write_text(fd, "rank ");
    write_text(fd, format_long(rank, r, sizeof r));
    write_text(fd, " items ");
    write_text(fd, format_long(begin, a, sizeof a));
    write_text(fd, "-");
    write_text(fd, format_long(end - 1, b, sizeof b));
  };
  for (int rank = 0; rank < ranks; ++rank) {
    write_block(rank, h[rank].begin.load(), h[rank].end.load());
    const long next_begin = h[rank].next_begin.load();
    if (next_begin >= 0) {
      write_text(fd, " (then ");
      write_text(fd, format_long(next_begin, a, sizeof a));
      write_text(fd, "-");
      write_text(fd, format_long(h[rank].next_end.load() - 1, b, sizeof b));
      write_text(fd, ")");
    }
  }
  if (any) write_text(fd, "\n");
}

}  // namespace flexure::parallel
