#pragma once
// Dimensional PRBM of a half constant-force mechanism (MechanismDesign) over its stroke: slider
// force by virtual work (thesis eq. 2.14 scaled by eq. 2.13, F = k1 Phi/r2; class 1B F = k2
// Phi'/r2, eq. 2.19), the pin force between crank and coupler by statics of the two PRB links, and
// the largest stress of every flexible segment:
//   s pivot: sigma = K psi h/(2I) + |P|/A   (bending by the spring moment, Howell eq. 5.14, plus
//            the link force carried axially -- an upper bound on the axial part);
//   l segment: sigma = M_clamp h/(2I) + |P|/A with M_clamp the moment of the pin force P about the
//            clamp (a fixed-pinned segment carries no other load), the clamp 0.15 l behind its
//            characteristic pivot along the clamp tangent (Howell eq. 5.49 geometry).
#include <array>
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

// Slider displacements Delta x = k stroke/points, k = 1..points (Delta x = 0 is left out: the
// straight position is the 0/0 point of eq. 2.14 and a bifurcation of the exact model).
std::vector<double> stroke_displacements(const MechanismDesign& design, int points);

struct PrbmState {
  double displacement = 0.0;  // Delta x, m
  double theta2 = 0.0;        // crank angle, rad
  double theta3 = 0.0;        // principal coupler angle, rad (<= 0)
  double force = 0.0;         // slider input force F, N (positive = pushing the slider inward)
  double pin_force_x = 0.0;   // force of the coupler on the crank at pivot 2, N
  double pin_force_y = 0.0;
  std::array<double, 3> stress{};  // largest stress of each flexible pivot, Pa (0 for a pin)
  // The bending moment behind each stress with its sign (K psi at an s pivot, the pin force's
  // moment about the clamp of an l segment), N m: whether a fibre's stress changes sign over a
  // stroke (materials_fatigue.h).
  std::array<double, 3> moment{};
};

// PRBM state at one slider displacement 0 < Delta x <= toggle stroke (design finalised).
PrbmState prbm_state(const MechanismDesign& design, double displacement);

struct PrbmStrokeResult : SolveStatus {
  std::vector<double> displacement;           // m
  std::vector<double> force;                  // N
  std::array<std::vector<double>, 3> stress;  // Pa, per pivot (empty for a pin)
  std::array<double, 3> max_stress{};         // over the stroke, Pa
  double max_stress_all = 0.0;                // largest of max_stress, Pa
  int critical_pivot = 0;                     // pivot of max_stress_all (1..3)
  double safety_factor = 0.0;                 // yield_strength/max_stress_all
  double mean_force = 0.0;                    // N
  double percent_constant_force = 0.0;        // 100 min F/max F (thesis eq. 5.22); 0 when
                                              // the force vanishes (constant_force.h)
  bool force_vanishes = false;      // the force is zero within the stroke (or changes sign)
  bool force_changes_sign = false;  // the force takes both signs over the stroke
  // converged(): closed form: all values finite
  // iterations: stroke points
  // residual: largest |F_statics - F_virtual_work|/|F| (two routes to the force)
};

PrbmStrokeResult prbm_stroke(const MechanismDesign& design, int points);

}  // namespace flexure::mechanism
