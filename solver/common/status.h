#pragma once
// The status of every result, the errors and the stability verdict in one header: SolveStatus with
// its termination and warnings, InvalidInput, OutsideMethodDomain and NoConvergence, Stability.
//
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
//
// Error channels shared by every solver and the command-line tool.
//
// Bad input (NaN, negative length, unknown name, a load outside a method's domain) is reported by
// throwing InvalidInput; the CLI maps it to exit code 2. A method that cannot produce a converged
// solution returns a result with converged == false and a message; the CLI maps that to exit
// code 3. Programmer errors are not caught.
//
// The stability verdict of an equilibrium: the vocabulary every layer reports (docs/stability.md).
//
// An equilibrium of a conservative system is stable when the second variation of its total
// potential energy, taken over the variations its constraints admit, is positive definite; its
// number of negative directions (the Morse index) says in how many independent ways the energy
// decreases. The verdict carries that index and a dimensionless margin, the lowest eigenvalue of
// the second variation measured against the unloaded bending stiffness (for a beam or chain:
// 1 unloaded, 1 - P/P_cr for a straight column under an axial load P, 0 at a buckling or limit
// point, negative when unstable; docs/stability.md, "The margin").
//
// Kinds and their stable names (the values of the JSON key `stability`, a contract):
//   kStable          "stable"            margin > tolerance: a strict minimum of the energy
//   kUnstable        "unstable"          at least one eigenvalue below -tolerance
//   kCritical        "critical"          no eigenvalue below -tolerance, lowest within tolerance of
//   0 kNotConservative "not_conservative"  a follower load: no potential energy judges stability
//   kNotChecked      "not_checked"       not computed (the message says why)
// index and margin are meaningful for the first three (judged()); otherwise both are 0.
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace flexure {

class InvalidInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Input that is valid but outside one method's domain (e.g. a load beyond the elliptic solver's
// range): another method may solve it, so `--method auto` can fall back. Still exit code 2 when
// the user named the method.
class OutsideMethodDomain : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

class NoConvergence : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws InvalidInput naming `what` unless `value` is a finite number.
void require_finite(double value, const std::string& what);

}  // namespace flexure

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
  kUnits,            // a quantity whose unit looks mistaken (solver/common/section.h)
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

namespace flexure {

enum class StabilityKind { kStable, kUnstable, kCritical, kNotConservative, kNotChecked };

// "stable", "unstable", "critical", "not_conservative", "not_checked".
std::string_view stability_name(StabilityKind kind);
// The inverse of stability_name; throws InvalidInput listing the names otherwise.
StabilityKind stability_kind_from_name(std::string_view name);

// Default tolerance on the margin below which an equilibrium is called critical. The margin of a
// column is 1 - P/P_cr, so 1e-6 means "within a millionth of the critical load"; it is about 100
// times the accuracy of the chain's margin on smooth shapes (docs/stability.md, "Accuracy"), so a
// state is not called critical because of discretisation error alone, nor stable or unstable
// while it is within that error of a critical state.
inline constexpr double kCriticalMarginTolerance = 1e-6;

struct Stability {
  StabilityKind kind = StabilityKind::kNotChecked;
  int index = 0;        // negative directions: eigenvalues below -critical tolerance
  double margin = 0.0;  // lowest eigenvalue of the second variation / bending stiffness (<= 1)
  std::string message;  // what was found, in words (never parsed by code)

  // Whether the energy judged this equilibrium (stable, unstable or critical).
  bool judged() const noexcept {
    return kind == StabilityKind::kStable || kind == StabilityKind::kUnstable ||
           kind == StabilityKind::kCritical;
  }
  bool stable() const noexcept { return kind == StabilityKind::kStable; }
};

// The verdict from the index and margin a second-variation computation found, with the message
// every method gives: kUnstable when index > 0, else kCritical when margin <= tolerance, else
// kStable. `subject` names what is judged in messages ("the beam", "the chain", "the mechanism").
Stability classify_stability(int index,
                             double margin,
                             double critical_tolerance = kCriticalMarginTolerance,
                             std::string_view subject = "the beam");

// A follower load: the energy cannot judge stability (index 0, margin 0, the reason in words).
Stability not_conservative_stability(std::string_view why);
// Not computed: index 0, margin 0, the reason in words.
Stability not_checked_stability(std::string_view why);

}  // namespace flexure
