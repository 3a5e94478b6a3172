#include "cli/slow_progress.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include "flexure/io/parallel/mpi_world.h"

namespace flexure::cli {

namespace {

// Under mpirun a rank cannot tell whether the user watches a terminal (mpirun gives ranks a pty
// whether or not its own output is one, and forwards stderr through a pipe): rank 0 prints whole
// lines, every kEverySeconds, which suit a terminal and a batch job's log alike; short runs print
// nothing.
std::function<void(std::size_t, std::size_t)> mpi_progress(std::string label) {
  if (parallel::launched_rank() != 0) return nullptr;
  constexpr double kEverySeconds = 10.0;
  struct State {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double next = kEverySeconds;
  };
  auto state = std::make_shared<State>();
  return [state, label = std::move(label)](std::size_t done, std::size_t total) {
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - state->start).count();
    if (t < state->next) return;
    state->next = t + kEverySeconds;
    std::fprintf(stderr,
                 "%s: %zu/%zu (%.0f %%, %.0f s, %d ranks)\n",
                 label.c_str(),
                 done,
                 total,
                 total > 0 ? 100.0 * static_cast<double>(done) / static_cast<double>(total) : 100.0,
                 t,
                 parallel::launched_size());
    std::fflush(stderr);
  };
}

}  // namespace

std::function<void(std::size_t, std::size_t)> slow_progress(std::string label) {
  if (parallel::launched_size() > 1) return mpi_progress(std::move(label));
  if (!::isatty(STDERR_FILENO)) return nullptr;
  // Below this a run feels instant; a progress line would only flicker.
  constexpr double kQuietSeconds = 1.0;
  struct State {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    bool shown = false;
  };
  auto state = std::make_shared<State>();
  return [state, label = std::move(label)](std::size_t done, std::size_t total) {
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - state->start).count();
    if (t < kQuietSeconds && !state->shown) return;
    state->shown = true;
    std::fprintf(stderr, "\r%s: %zu/%zu (%.1f s)", label.c_str(), done, total, t);
    if (done >= total) std::fputc('\n', stderr);
    std::fflush(stderr);
  };
}

}  // namespace flexure::cli
