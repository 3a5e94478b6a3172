// A test program for tests/mpi (FLEXURE_MPI=ON only): runs parallel::distribute over `total` items
// whose cost is a sleep, and prints on rank 0 which rank computed each item, one line per item
// ("round item rank"), so that a test can check that every item was computed once and where they
// went. One rank is a straggler: its first block takes SLOW_SECONDS per item, every other block
// OTHER_SECONDS per item (a slow node, or an item far costlier than the others). ROUNDS runs
// distribute() that many times in a row, as a command with several studies would.
// Usage: distribution_probe TOTAL MAX_BLOCK SLOW_RANK SLOW_SECONDS OTHER_SECONDS [ROUNDS]
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/work_distribution.h"

int main(int argc, char** argv) {
  if (argc != 6 && argc != 7) {
    std::fprintf(stderr,
                 "usage: %s TOTAL MAX_BLOCK SLOW_RANK SLOW_SECONDS OTHER_SECONDS [ROUNDS]\n",
                 argv[0]);
    return 2;
  }
  const long total = std::atol(argv[1]);
  const int slow_rank = std::atoi(argv[3]);
  const double slow = std::atof(argv[4]);
  const double other = std::atof(argv[5]);
  const int rounds = argc == 7 ? std::atoi(argv[6]) : 1;
  namespace parallel = flexure::parallel;
  const parallel::World& w = parallel::world();
  bool first_block = true;
  for (int round = 0; round < rounds; ++round) {
    std::vector<std::int64_t> mine;  // items this rank computed, in order
    parallel::DistributionOptions options;
    options.max_block = std::atol(argv[2]);
    parallel::distribute(
        total,
        [&](long begin, long end) -> parallel::BlockWriter {
          const bool slowed = first_block && w.rank() == slow_rank;
          first_block = false;
          for (long i = begin; i < end; ++i) {
            std::this_thread::sleep_for(std::chrono::duration<double>(slowed ? slow : other));
          }
          // Recorded by the writer, on the thread that calls MPI (rank 0 computes on another).
          return [&mine, begin, end] {
            for (long i = begin; i < end; ++i) mine.push_back(i);
          };
        },
        options);
    const std::vector<std::int64_t> items = w.gather(mine);
    const std::vector<std::int64_t> counts =
        w.gather(std::vector<std::int64_t>{static_cast<std::int64_t>(mine.size())});
    if (w.root()) {
      std::size_t at = 0;
      for (std::size_t r = 0; r < counts.size(); ++r) {
        for (std::int64_t k = 0; k < counts[r]; ++k) {
          std::printf("%d %lld %zu\n", round, static_cast<long long>(items[at++]), r);
        }
      }
    }
  }
  return 0;
}
