#pragma once
// Items of a study divided over the ranks of world() with dynamic load balancing
// (docs/scaling.md "How the work is divided"): every rank's first block is fixed in advance (the
// first blocks in rank order, so that each rank starts at once and has work), rank 0 hands out the
// later blocks on request, and a rank asks for its next block as soon as it starts one; rank 0
// answers at once while many blocks are left (the rank then never waits), else once the rank is
// free (a block given ahead would wait behind a slow one while other ranks idle). Blocks shrink
// towards the end (a share of what is left), so that ranks finish together however the cost varies
// per item (exact strokes, optimisations). Rank 0 computes too, on a second thread, while its first
// thread answers requests and writes; in a run of one rank the blocks are computed in order on the
// calling thread.
//
// A block is computed by `compute(begin, end)` (on any thread, without MPI), which returns what is
// left to do on the calling thread: writing the block (e.g. Hdf5Dataset::write_range of a
// collective file). A failure in either is thrown as RankFailure naming the rank and the items,
// after which the run must end with World::abort (cli/cli_common.cpp does so).
#include <functional>
#include <string>
#include <vector>

namespace flexure::parallel {

using BlockWriter = std::function<void()>;
using BlockCompute = std::function<BlockWriter(long begin, long end)>;

struct DistributionOptions {
  long max_block = 1;  // at most this many items in one block
  // At least this many (but for the last block): cheap items (a sweep's loads, about a
  // microsecond each) in blocks worth a message and a write of their own. Lowered to
  // total / (2 ranks) when that is smaller, so that every rank has a block.
  long min_block = 1;
  // Rank 0, on the calling thread: items done over all ranks (counted per finished block).
  std::function<void(long done, long total)> progress;
  // Names an item in a failure message, e.g. "R = 1.2, d = 30 %" (null: the index only).
  std::function<std::string(long item)> describe;
};

// Computes items [0, total) over the ranks and returns the number this rank computed. Every rank
// calls it with the same total and options; it ends with a barrier, so that the messages of one
// call never meet the next.
long distribute(long total, const BlockCompute& compute, const DistributionOptions& options);

// Items computed by each rank in this process's distribute() calls so far (rank 0; empty in a run
// of one rank): the balance that the tool reports at the end of an MPI run.
std::vector<long> items_per_rank();

// For a signal handler (async-signal-safe): writes the blocks in progress on the ranks, as rank 0
// knows them ("rank 1 items 40-59 (then 60-79)"), to `fd`; nothing outside a distribute() on
// rank 0, and only the first call of a distribute() writes. A distribute() on rank 0 installs the
// handlers of io/platform/temp_file_cleanup.h, which call it, and one for the SIGCONT with which
// mpirun opens its stop sequence (work_distribution.cpp: the SIGTERM after it leaves milliseconds).
void write_blocks_in_progress(int fd);

}  // namespace flexure::parallel
