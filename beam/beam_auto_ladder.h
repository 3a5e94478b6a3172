#pragma once
// `--method auto` across the model ladder for Howell's free cantilever (docs/models.md "auto
// across the ladder"): the cheapest rung, by the times of data/ladder_auto_error_map.csv, whose
// error at the load is within the tolerance, before the exact methods.
//
// A rung qualifies when its mapped error bound E per length (ladder_selector.h: 1.5 times the
// largest error at the measured loads around this one) gives, with the tip displacement d of its
// own answer, a relative error bound E / (d - E) within problem.tolerance (the relative tip error
// of --tol, beam_problem.h); the 1R PRBM also has to be inside Howell's validity limits. The
// rungs are tried cheapest first and only while they are cheaper than the elliptic solution at
// this load; a rung whose bound cannot meet the tolerance whatever its answer (E / 2 > tolerance,
// as the exact displacement is at most 2 l) is passed over without a solve.
#include <optional>
#include <string>

#include "flexure/beam/beam_problem.h"

namespace flexure {

struct LadderAutoOutcome {
  // The chosen rung's answer, with method_reason, expected_error (relative) and
  // expected_error_per_length set; empty when no rung cheaper than the elliptic solution meets
  // the tolerance (or the ladder does not apply).
  std::optional<BeamSolution> solution;
  // Without a solution: why each cheaper rung was passed over, for the exact method's reason
  // (judged true), or that the load is off the map (judged false: the rungs were not judged, and
  // the 1R PRBM's own measured map still may be); empty when the ladder does not apply (not a
  // free cantilever with dead loads and a given load, a stable equilibrium asked for, model
  // settings other than the map's).
  std::string verdict;
  bool judged = false;
};

LadderAutoOutcome solve_by_ladder(const BeamProblem& problem);

// A named rung's answer to a problem the map covers: its mapped error bound per length and the
// relative bound from its tip (expected_error, expected_error_per_length); unchanged otherwise.
void attach_mapped_error(const BeamProblem& problem, BeamSolution& solution);

}  // namespace flexure
