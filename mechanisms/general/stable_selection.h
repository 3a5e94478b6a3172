#pragma once
// `mechanism analyze FILE --stable` for a general mechanism (issue 31; docs/mechanisms.md
// "Stable equilibria (--stable)"): from a traced path, at every grid value of the controlled
// quantity, the equilibrium that is stable under that control.
//
// The path (solve_general_prbm, solve_general_exact, solve_general_mixed) records a point wherever
// it crosses a grid value -- several at one value where it has turned back at limit points (under
// force control the bistable switch at 0.1 N m: once on each stable branch and once on the
// unstable one between them). The selection walks the grid from start to stop and keeps, at each
// value, a recorded point whose verdict under the input's control is stable: of several, the one
// nearest the point kept at the value before (in the input coordinate under force control, in the
// input load under displacement control), so that the mechanism stays on its branch while that
// branch is stable and moves to another where it ends -- the quasi-static path of a slowly varied
// input, which snaps at a limit point of a dead load. At the first value the path's first stable
// point there is kept (the branch the path starts on).
//
// A grid value where the path recorded no stable point is reported: the model does not switch
// branches at bifurcations (an unstable branch whose stable neighbour branches off is not traced),
// and no stable equilibrium was found there.
#include <cstddef>
#include <functional>
#include <string>

#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"

namespace flexure::mechanism::general {

struct StableSelection {
  // The path's result with `points` replaced by the selected ones, one per grid value in grid
  // order (where none is stable: the first point the path recorded there); equilibria and limit
  // points unchanged (they are the path's).
  GeneralPrbmResult result;
  bool stable = false;  // every grid value has a stable point
  int grid_values = 0, without_stable = 0, snaps = 0;
  // What was done, for people: "not needed: ...", the snaps between grid values, or where no
  // stable equilibrium was found.
  std::string search;
};

// The selection for `path`, traced for `mechanism` (its input's grid and control). Throws
// InvalidInput for a path with no points. `progress(done, count)`, if set, is called after each
// grid value (count: the input's); it scans the path's points once per value, so a path of many
// points on a fine grid takes a while. A caller stops it by throwing from `progress` (the
// exception propagates; nothing is returned).
StableSelection select_stable_points(
    const GeneralMechanism& mechanism,
    const GeneralPrbmResult& path,
    const std::function<void(std::size_t done, std::size_t total)>& progress = {});

}  // namespace flexure::mechanism::general
