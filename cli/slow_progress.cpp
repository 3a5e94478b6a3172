#include "cli/slow_progress.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <utility>

#include "flexure/io/platform/mpi_world.h"

namespace flexure::cli {

namespace {

// The thread's ProgressSink (empty: none).
thread_local std::function<void(std::size_t, std::size_t)> current_sink;

// Seconds between progress lines under mpirun: FLEXURE_PROGRESS_SECONDS (a batch job may want
// them rarer), else 10 (docs/scaling.md).
double progress_interval() {
  constexpr double kDefault = 10.0;
  const char* text = std::getenv("FLEXURE_PROGRESS_SECONDS");
  if (text == nullptr || *text == '\0') return kDefault;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  if (*end != '\0' || !(seconds > 0.0) || !std::isfinite(seconds)) {
    std::fprintf(stderr,
                 "flexure: warning: FLEXURE_PROGRESS_SECONDS=%s is not a positive number of "
                 "seconds; progress every %.0f s\n",
                 text,
                 kDefault);
    return kDefault;
  }
  return seconds;
}

// Under mpirun a rank cannot tell whether the user watches a terminal (mpirun gives ranks a pty
// whether or not its own output is one, and forwards stderr through a pipe): rank 0 prints whole
// lines, every progress_interval(), which suit a terminal and a batch job's log alike; short runs
// print nothing.
std::function<void(std::size_t, std::size_t)> mpi_progress(std::string label) {
  if (parallel::launched_rank() != 0) return nullptr;
  const double every = progress_interval();
  struct State {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double next = 0.0;
  };
  auto state = std::make_shared<State>();
  state->next = every;
  return [state, every, label = std::move(label)](std::size_t done, std::size_t total) {
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - state->start).count();
    if (t < state->next) return;
    state->next = t + every;
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

ProgressSink::ProgressSink(std::function<void(std::size_t, std::size_t)> sink)
    : previous_(std::exchange(current_sink, std::move(sink))) {}

ProgressSink::~ProgressSink() { current_sink = std::move(previous_); }

std::function<void(std::size_t, std::size_t)> stoppable_progress(std::string label) {
  std::function<void(std::size_t, std::size_t)> terminal = slow_progress(std::move(label));
  if (!current_sink) return terminal;
  return
      [terminal = std::move(terminal), sink = current_sink](std::size_t done, std::size_t total) {
        if (terminal) terminal(done, total);
        sink(done, total);
      };
}

}  // namespace flexure::cli
