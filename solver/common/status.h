#pragma once
// The common status of every solve (docs/architecture.md, "One result vocabulary").
//
// Every result type of the library derives from SolveStatus, in the style of Ceres'
// Solver::Summary: how the solve ended (a termination enum that code branches on), a message for
// people (what stopped it and how far it got), the iterations spent and the residual reached.
// Code never inspects the message text; it reads `termination` or `converged()`.
//
// Warnings are the one channel for what a person should know about a result that is still
// returned: a stroke clamped at the toggle position, a force that vanishes, a unit that looks
// mistaken. The library adds them to the result (never prints); the tool prints each as
// "flexure: warning: TEXT" on stderr and the Python module raises FlexureWarning for each.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace flexure {

enum class Termination {
  kConverged,      // the answer meets the requested tolerance
  kNoConvergence,  // the iteration or continuation stopped without meeting it
  kLimitPoint,     // a limit point (fold) of the load path was reached: past it the structure snaps
  kInvalidInput,   // the input is outside the method's domain; nothing was solved
  kInfeasible,     // solved, but no answer meets the specification (a design constraint binds)
};

// Stable lower-case names: "converged", "no_convergence", "limit_point", "invalid_input",
// "infeasible" (the values of the JSON key "termination").
std::string_view termination_name(Termination termination);

// "; the path passed N limit point(s): under load control the beam would snap at the first, at
// load factor X", or "" without limit points: the note every continuation adds to its branch text.
std::string limit_points_note(int limit_points, double first_limit_load_factor);

// What a warning is about, for code that filters them (the text is for people).
enum class WarningKind {
  kUnits,            // a quantity whose unit looks mistaken (solver/common/quantity.h)
  kOutsideValidity,  // a model used outside the range its source validated
  kStrokeClamped,    // a requested stroke past the toggle position, clamped (docs/cfm.md §1.3)
  kForceVanishes,    // a force that is zero or changes sign within the stroke (Xi' is 0)
  kYield,            // a stress at or past the yield strength
  kSafetyFactor,     // a safety factor below the one asked for
  kDesign,           // a design that misses part of its specification
  kOther,
};

// Stable lower-case names: "units", "outside_validity", "stroke_clamped", "force_vanishes",
// "yield", "safety_factor", "design", "other".
std::string_view warning_kind_name(WarningKind kind);

struct Warning {
  WarningKind kind = WarningKind::kOther;
  std::string text;  // one sentence for people, without a "warning:" prefix

  bool operator==(const Warning&) const = default;
};

struct SolveStatus {
  Termination termination = Termination::kNoConvergence;
  std::string message;    // what stopped the solve and how far it got; empty or a note on success
  int iterations = 0;     // the method's own count (its results say what it counts)
  double residual = 0.0;  // the method's residual at the returned point (its results say which)
  // For people, in the order they arose; empty for most results (no allocation then).
  std::vector<Warning> warnings;

  bool converged() const noexcept { return termination == Termination::kConverged; }
  // kConverged when `ok`, else kNoConvergence; for the common two-way outcome of an iteration.
  void set_converged(bool ok) noexcept {
    termination = ok ? Termination::kConverged : Termination::kNoConvergence;
  }
  void warn(WarningKind kind, std::string text) { warnings.push_back({kind, std::move(text)}); }
  const SolveStatus& status() const noexcept { return *this; }
};

}  // namespace flexure
