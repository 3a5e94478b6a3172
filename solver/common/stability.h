#pragma once
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
#include <string>
#include <string_view>

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
