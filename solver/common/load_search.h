#pragma once
// Inverse problems solved with any forward solver: the load alpha2 at which a tip quantity (tip
// angle, tip deflection) reaches a target, with n and mu fixed.
//
// |alpha2| is scanned on a geometric grid from min_alpha2, both signs interleaved, so that the
// load of smallest magnitude that reaches the target is found first. Each sign change of
// quantity - target is refined by Brent's method and then *verified*: the forward solve at the
// root must reach the target within target_tolerance. A sign change across a jump of the
// quantity (a fold of the load path, a change of branch) is not a root and fails the check; the
// scan then goes on. So an inverse solve that reports `found` always hit its target.
#include <functional>
#include <optional>
#include <string>

namespace flexure {

struct LoadSearchOptions {
  double min_alpha2 = 1e-3;           // first grid point of |alpha2|
  double max_alpha2 = 1e4;            // last grid point of |alpha2|
  double growth = 1.5;                // grid ratio
  double relative_tolerance = 1e-13;  // on alpha2 at the bracketed root
  double target_tolerance = 1e-10;    // |quantity - target| accepted at the returned load
  int max_solves = 2000;              // forward solves in all (a failure comes fast)
};

enum class LoadSearchStatus {
  kFound,        // alpha2 reaches the target within target_tolerance
  kUnreachable,  // no load in the scanned range brackets the target
  kMissed,       // brackets were found, but none holds a root that reaches the target (jumps)
};

struct LoadSearchResult {
  LoadSearchStatus status = LoadSearchStatus::kUnreachable;
  bool found() const { return status == LoadSearchStatus::kFound; }
  double alpha2 = 0.0;              // the load (found), or the load of the closest approach
  double reached = 0.0;             // the quantity at alpha2
  double residual = 0.0;            // |reached - target|
  int solves = 0;                   // forward solves made
  double reached_alpha2_max = 0.0;  // largest |alpha2| at which forward solves succeeded
  bool stopped_early = false;       // a forward solve failed (or left the method's range) before
                                    // max_alpha2 on some side
  bool scanned_to_max = false;      // some side was scanned up to max_alpha2
  // kMissed: the first jump across the target, between two scanned loads.
  double jump_alpha2_from = 0.0, jump_alpha2_to = 0.0;
  double jump_value_from = 0.0, jump_value_to = 0.0;
  std::string message;  // why nothing was found
};

// `quantity(alpha2)` returns the tip quantity, or nullopt if the forward solve failed there or the
// load is outside the method's range (the scan on that side stops at the first failure).
// `at_zero` is its value for the unloaded beam.
LoadSearchResult find_load_for_target(
    const std::function<std::optional<double>(double alpha2)>& quantity,
    double target,
    double at_zero,
    const LoadSearchOptions& options = {});

// Refines a load near `guess` (from another method, e.g. the exact elliptic inverse for a
// discretised model): brackets the target by steps growing from `relative_step` |guess| around
// the guess, then Brent and the same verification. Returns kUnreachable when no bracket is found
// within a factor of two of the guess.
LoadSearchResult refine_load_for_target(
    const std::function<std::optional<double>(double alpha2)>& quantity,
    double target,
    double guess,
    double relative_step,
    const LoadSearchOptions& options = {});

}  // namespace flexure
