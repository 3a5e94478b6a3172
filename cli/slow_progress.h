#pragma once
// A progress line on stderr for work that is usually quick but can take long (an exact stroke near
// a fold, where substeps multiply the work): silent for the first second, then "\r<label>: k/n
// (t s)" while stderr is a terminal; nothing at all when it is not (scripts, CI logs). Under
// mpirun: rank 0 prints "<label>: k/n (p %, t s, N ranks)" lines every 10 s, the items done over
// all ranks.
#include <cstddef>
#include <functional>
#include <string>

namespace flexure::cli {

std::function<void(std::size_t done, std::size_t total)> slow_progress(std::string label);

// The progress run_command's caller (command_runner.h: the Python module) wants of every step of
// the command's long work, on the command's thread, while the object lives: run_command installs
// its `progress` argument for the call, as it does its output capture. The sink may throw to stop
// the command; only stoppable_progress's hooks call it.
class ProgressSink {
 public:
  explicit ProgressSink(std::function<void(std::size_t done, std::size_t total)> sink);
  ~ProgressSink();
  ProgressSink(const ProgressSink&) = delete;
  ProgressSink& operator=(const ProgressSink&) = delete;

 private:
  std::function<void(std::size_t, std::size_t)> previous_;
};

// slow_progress(label) and, at every step, the ProgressSink of the thread that asks for it (if
// any). For work whose progress hook may throw to stop it: called on the command's own thread,
// its state RAII (no worker thread left running, an output file atomic), such as the dynamics
// study's rows, the exact CFM design's strokes, a mechanism's exact stroke.
std::function<void(std::size_t done, std::size_t total)> stoppable_progress(std::string label);

}  // namespace flexure::cli
