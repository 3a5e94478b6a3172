#pragma once
// Inverse problems solved with any forward solver: the load alpha2 at which a tip quantity (tip
// angle, tip deflection) reaches a target, with n and mu fixed.
//
// |alpha2| is scanned on a geometric grid from min_alpha2 (positive side first, then negative), the
// first sign change of quantity - target is refined by Brent's method, so the smallest load that
// reaches the target is returned. Used by the elliptic solver's inverses with an end moment and by
// `flexure beam --theta0/--b-over-l` with the shooting and chain methods.
#include <functional>
#include <optional>
#include <string>

namespace flexure {

struct LoadSearchOptions {
  double min_alpha2 = 1e-3;   // first grid point of |alpha2|
  double max_alpha2 = 1e4;    // last grid point of |alpha2|
  double growth = 1.5;        // grid ratio
  double relative_tolerance = 1e-13;  // on alpha2 at the bracketed root
};

struct LoadSearchResult {
  bool found = false;
  double alpha2 = 0.0;
  int solves = 0;       // forward solves made
  std::string message;  // why nothing was found
};

// `quantity(alpha2)` returns the tip quantity, or nullopt if the forward solve failed there (the
// scan on that side stops at the first failure). `at_zero` is its value for the unloaded beam.
LoadSearchResult find_load_for_target(
    const std::function<std::optional<double>(double alpha2)>& quantity,
    double target,
    double at_zero,
    const LoadSearchOptions& options = {});

}  // namespace flexure
