#include "cli/slow_progress.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>

namespace flexure::cli {

std::function<void(std::size_t, std::size_t)> slow_progress(std::string label) {
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
