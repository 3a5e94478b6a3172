#pragma once
// Inversions of the constant-force slider mechanisms (Weight 2001 §3.2.4 and Fig. 3.2;
// Howell §10.1.2, Fig. 10.2 right-hand column): the slider block is fixed and the "ground" block
// slides. Every parameter value is the same and the relative motion of the two blocks is the same,
// so force, stresses and the exact solution are those of the original; what changes is which body
// is fixed (mounting, and the moving mass in dynamics).
//
// Described form (Howell's mirrored column): read from the fixed body, the pivot string is
// reversed (lpp -> ppl), r2 <-> r3 and k1 <-> k3, and pivot i of the original is pivot 4 - i of
// the inversion (the flexure that was at the ground is at the sliding block). A MechanismDesign
// with `inverted = true` keeps the ORIGINAL fields (the frame every model computes in); the
// functions here give its described form for output.
//
// Only the type-asymmetric configurations have a distinct inversion: spp', lpp', plp' (= pl3p,
// the middle beam on the other link), ssp', slp', lps'. psp, sps and sss read the same mirrored;
// their "inversion" is a design of the same configuration with R' = 1/R, K1' = K1/K2, K2' = 1/K2.
#include <array>
#include <optional>
#include <string>

#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism {

// True for spp, lpp, plp, ssp, slp, lps (the configurations with a primed mirror).
bool config_has_inversion(const std::string& config);
// The mirrored pivot string: ppl, ppl, pl3p (plp: the middle beam becomes link 3), pss, pls, spl;
// psp, sps, sss unchanged.
std::string mirrored_config(const std::string& config);

// The inversion of `design` (name + "'", `inverted` toggled, note prefixed). Inverting twice gives
// the original back. Throws InvalidInput for psp, sps, sss (see above).
MechanismDesign invert(const MechanismDesign& design);

// "1A-lpp'" or "1A-lpp-inv" (any case) -> "1A-lpp"; nullopt for a name without the suffix.
std::optional<std::string> inversion_base_name(const std::string& name);

// Described (mirrored for an inversion, else as stored) geometry for output.
struct DescribedDesign {
  std::string config;                 // "ppl" for 1A-lpp', "lpp" for 1A-lpp
  double r2 = 0.0;                    // link at the fixed body, m
  double r3 = 0.0;                    // link at the sliding body, m
  std::array<JointDesign, 3> joints;  // pivot 1 at the fixed body ... pivot 3 at the sliding one
  std::string fixed_body;             // "ground" or "slider block"
};
DescribedDesign described_form(const MechanismDesign& design);

// Described pivot number (1..3) of the stored pivot `pivot` (4 - pivot for an inversion).
int described_pivot(const MechanismDesign& design, int pivot);
// Per-pivot values (index 0..2 = stored pivots 1..3) in described pivot order.
std::array<double, 3> to_described(const MechanismDesign& design, const std::array<double, 3>& v);

// PRBM slider force of an inversion at Delta x, N: virtual work (prbm_virtual_work.h) on the
// DESCRIBED mechanism (r2' = r3, r3' = r2, k' = (k3, k2, k1)) -- an independent route to the force
// of the original, which mechanism_prbm.cpp computes with the thesis's Phi function.
double inverted_prbm_force(const MechanismDesign& design, double displacement);

}  // namespace flexure::mechanism
