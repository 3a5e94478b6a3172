#pragma once
// The common status of every solve (docs/architecture.md, "One result vocabulary").
//
// Every result type of the library derives from SolveStatus, in the style of Ceres'
// Solver::Summary: how the solve ended (a termination enum that code branches on), a message for
// people (what stopped it and how far it got), the iterations spent and the residual reached.
// Code never inspects the message text; it reads `termination` or `converged()`.
#include <string>
#include <string_view>

namespace flexure {

enum class Termination {
  kConverged,      // the answer meets the requested tolerance
  kNoConvergence,  // the iteration or continuation stopped without meeting it
  kLimitPoint,     // a limit point (fold) of the load path was reached: past it the structure snaps
  kInvalidInput,   // the input is outside the method's domain; nothing was solved
};

// Stable lower-case names: "converged", "no_convergence", "limit_point", "invalid_input" (the
// values of the JSON key "termination").
std::string_view termination_name(Termination termination);

// "; the path passed N limit point(s): under load control the beam would snap at the first, at
// load factor X", or "" without limit points: the note every continuation adds to its branch text.
std::string limit_points_note(int limit_points, double first_limit_load_factor);

struct SolveStatus {
  Termination termination = Termination::kNoConvergence;
  std::string message;    // what stopped the solve and how far it got; empty or a note on success
  int iterations = 0;     // the method's own count (its results say what it counts)
  double residual = 0.0;  // the method's residual at the returned point (its results say which)

  bool converged() const noexcept { return termination == Termination::kConverged; }
  // kConverged when `ok`, else kNoConvergence; for the common two-way outcome of an iteration.
  void set_converged(bool ok) noexcept {
    termination = ok ? Termination::kConverged : Termination::kNoConvergence;
  }
  const SolveStatus& status() const noexcept { return *this; }
};

}  // namespace flexure
