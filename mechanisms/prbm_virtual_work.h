#pragma once
// Slider force of a PRBM slider-crank with ANY set of torsional springs, by the principle of
// virtual work written directly (Howell eq. 6.50, §10.1.1; the energy V = sum k_i psi_i^2/2,
// eq. 11.6):
//
//   F = dV/dDelta x = sum_i k_i psi_i dpsi_i/dDelta x,
//
// with psi_1 = theta2 (ground), psi_2 = theta2 - theta3 (middle), psi_3 = -theta3 (slider), all
// zero in the straight position, and the angle rates from differentiating the loop closure
//   r2 cos theta2 + r3 cos theta3 = r2 + r3 - Delta x,   r2 sin theta2 + r3 sin theta3 = 0:
//   dtheta2/dDelta x = cos theta3/(r2 sin(theta2 - theta3)),
//   dtheta3/dDelta x = -cos theta2/(r3 sin(theta2 - theta3)).
//
// This is deliberately a second code path next to the thesis's Phi function
// (mechanisms/cfm/slider_crank.h, eq. 2.14, which takes k1 -- or k2 in class 1B -- as reference):
// nothing here needs a reference spring, so a mirrored "ppl" with only k3 works, and the kinematics
// are built from the position of pivot 2 (circle intersection), not from asin/acos of eq. 2.1-2.2.
#include <array>

namespace flexure::mechanism {

struct VirtualWorkState {
  double theta2 = 0.0;           // crank angle, rad (pivot 2 above the slider axis: theta2 >= 0)
  double theta3 = 0.0;           // coupler angle, rad (<= 0)
  std::array<double, 3> psi{};   // spring rotations at pivots 1, 2, 3, rad
  std::array<double, 3> dpsi{};  // d psi_i / d Delta x, rad/m
  double force = 0.0;   // slider input force, N (positive pushes the slider towards the ground)
  double energy = 0.0;  // sum k_i psi_i^2 / 2, J
  // The second derivative of the energy along the stroke, the slider's stiffness under a dead load
  // (docs/stability.md "Mechanisms"):
  //   d^2V/dDelta x^2 = dF/dDelta x = sum_i k_i (psi_i'^2 + psi_i psi_i''),   N/m,
  // and its part without the springs' preload, the stiffness the springs would give the slider at
  // this pose if they were unstressed (the PRBM's B, as int EI eta'^2 is the chain's):
  //   sum_i k_i psi_i'^2 > 0,   N/m.
  // psi_i'' from differentiating the loop-closure rates once more (prbm_virtual_work.cpp).
  double stiffness = 0.0;
  double unloaded_stiffness = 0.0;
  std::array<double, 3> d2psi{};  // d^2 psi_i / d Delta x^2, rad/m^2
};

// State at slider displacement 0 < Delta x <= the toggle stroke of (r2, r3); k = (k1, k2, k3) in
// N m/rad, any of them zero. Throws InvalidInput for r2, r3 <= 0, a negative spring or a Delta x
// outside (0, toggle].
VirtualWorkState virtual_work_state(double r2,
                                    double r3,
                                    const std::array<double, 3>& k,
                                    double displacement);

}  // namespace flexure::mechanism
