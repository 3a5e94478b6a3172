#pragma once
// The Halton low-discrepancy sequence (Halton 1960), used for deterministic multistart points
// of the design searches (cfm_synthesis.cpp, cfm_exact_refinement.cpp). Internal to the design
// layer.

namespace flexure::design {

// The i-th point (i >= 1) of the van der Corput sequence in base `base`, in (0, 1); bases 2, 3,
// 5 for the coordinates of a Halton point.
inline double halton(int i, int base) {
  double f = 1.0, r = 0.0;
  for (int k = i; k > 0; k /= base) {
    f /= base;
    r += f * (k % base);
  }
  return r;
}

}  // namespace flexure::design
