#pragma once
// The sections of a dimensioned constant-force mechanism that make the same force (docs/design.md
// "Sizing for the safety factor"). At fixed geometry every model of the mechanism sees its
// flexures only through E I_i (the PRBM springs k = EI/l, Howell eqs. 5.14 and 5.72; the
// inextensible elastica of the exact model), so every section with the same b_i h_i^3 makes the
// same force and the same percent constant force. The design's section rule fixes the ratios of
// the flexures to the primary one (eq. 8.7: h_i = tau_i h_p, b_i = w_i b_p), and the force fixes
// K = b_p h_p^3 (eq. 8.2), so the sections form a one-parameter family in the primary thickness t:
//   h_i = tau_i t,   b_i = w_i K/t^3.
// Along it the stresses grow with t: the bending stress M h/(2I) like t (M and I fixed), the axial
// stress |N|/(b h) like t^2. Every bound on a section is a bound on t.
#include <array>
#include <string>

#include "flexure/mechanisms/design/mechanism_synthesis.h"
#include "flexure/mechanisms/mechanism.h"

namespace flexure::design {

struct SectionFamily {
  double K = 0.0;                  // b_p h_p^3 of the primary flexure, m^4
  std::array<double, 3> tau{};     // h_i/h_p per pivot (0 for a pin)
  std::array<double, 3> w{};       // b_i/b_p per pivot (0 for a pin)
  std::array<double, 3> length{};  // flexible segment length per pivot, m (Table 8.1)

  double thickness(int i, double t) const { return tau[i] * t; }
  double width(int i, double t) const { return w[i] * K / (t * t * t); }
  // Sets the thickness and width of every flexible joint of `design` for primary thickness t.
  void apply(double t, mechanism::MechanismDesign& design) const;
};

// The family of `design` as it stands (its flexures' thicknesses and widths, `primary` 1..3).
SectionFamily family_of(const mechanism::MechanismDesign& design, int primary);

// What bounds t: the lower end (a width upper bound -- the range's upper end, width/thickness,
// width/length -- or the thickness range's lower end) and the upper end (the thickness range's
// upper end, the width range's lower end, or the slender-beam limits h/L <= 0.5 and b/h >= 1 of
// MechanismDesign::finalise), each with the reason that sets it. lo > hi: no section fits.
struct SectionInterval {
  double lo = 0.0;
  double hi = 0.0;
  std::string lo_reason, hi_reason;
};
SectionInterval section_interval(const SectionFamily& family,
                                 const MechanismSpec& spec,
                                 double l_tot);

// Largest ratio of width to thickness and of width to l_tot over the flexures at t.
double max_width_to_thickness(const SectionFamily& family, double t);
double max_width(const SectionFamily& family, double t);

}  // namespace flexure::design
