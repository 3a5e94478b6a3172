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

}  // namespace flexure::cli
