#pragma once
// What a general mechanism's solve reports at every point besides the input load, energy and
// stability (issue 31 item 2; docs/mechanisms.md "Reactions, stresses and shapes"): the joints'
// reactions and positions, the load the ground puts on the mechanism, and each flexure's end
// loads, its largest normal stress (bending plus axial, at both fibres, with the location) and
// its shape. SI throughout.
#include <Eigen/Dense>
#include <vector>

#include "flexure/mechanisms/general/general_mechanism.h"

namespace flexure::mechanism::general {

// A force (N) at a point and a moment (N m, counter-clockwise) about that point.
struct PointLoad {
  double fx = 0.0;
  double fy = 0.0;
  double moment = 0.0;
};

// A joint at one point: where its point of body b is (m), and the load body a puts on body b
// through it (the force at that point; the moment of a slider or weld, 0 for a pin). Body b puts
// the opposite on body a.
struct JointPointResult {
  double x = 0.0;
  double y = 0.0;
  PointLoad on_b;
};

// One flexure at one point.
struct FlexurePointResult {
  // The loads the flexure puts on its bodies: on body a at end a, on body b at end b (force at the
  // end, moment about it). For a flexure clamped into the ground the negated on_a is the ground's
  // reaction there.
  PointLoad on_a;
  PointLoad on_b;
  // The largest |sigma| over both fibres and the length (Pa), sigma = N_a/A -+ m c/I (c = h/2,
  // N_a = N . t tension positive, m the bending moment, a positive m compressing the fibre on the
  // +n side: n the normal left of the tangent); where it acts, from end a (m); the fibre (+1: the
  // +n side, -1 the other); the two fibres' stresses, the bending moment and the axial force at
  // that section.
  double max_stress = 0.0;
  double max_stress_at = 0.0;
  int max_stress_fibre = 1;
  double stress_pos_fibre = 0.0;
  double stress_neg_fibre = 0.0;
  double moment = 0.0;
  double axial_force = 0.0;
  // "shape": searched along the elastica's sampled shape (a parabola through the largest sample
  // and its neighbours); "ends": the larger of the two ends' (the PRBM and the ladder's models,
  // which give the end loads of Howell's characteristic-radius model, not the shape: Howell eqs.
  // 5.22-5.23 at the clamp).
  const char* max_from = "ends";
  // The shape in global coordinates (m), from end a to end b: the elastica sampled at equal arc
  // lengths (exact), the PRB linkage's joints (PRBM: end a, its pivots, end b), or the chord (a
  // model flexure of the mixed model).
  std::vector<double> shape_x, shape_y;
};

// The normal stresses of a section of `flexure` carrying bending moment m (N m) and axial force
// N_a (N, tension positive): {sigma at the +n fibre, at the -n fibre} = N_a/A -+ m c/I.
struct FibreStresses {
  double pos = 0.0;
  double neg = 0.0;
};
FibreStresses fibre_stresses(const Flexure& flexure, double moment, double axial);
// The same for the rectangle width x thickness (m) of a tapered flexure's section.
FibreStresses fibre_stresses(double width, double thickness, double moment, double axial);

// Keeps in `r` the section (at `s` m from end a, moment m, axial force N_a) whose |sigma| is
// largest; `first` replaces whatever `r` held.
void keep_most_stressed(
    FlexurePointResult& r, const Flexure& flexure, double s, double m, double axial, bool first);
// The same with the section width x thickness (m) there.
void keep_most_stressed(FlexurePointResult& r,
                        double width,
                        double thickness,
                        double s,
                        double m,
                        double axial,
                        bool first);

// The stress of a flexure whose end loads are known and whose shape is not (the PRBM, a ladder
// model): the sections at both ends, with the bending moment and axial force there. m_a, m_b:
// bending moments at end a and end b; axial_a, axial_b: N . t there.
void end_stresses(FlexurePointResult& r,
                  const Flexure& flexure,
                  double length,
                  double m_a,
                  double axial_a,
                  double m_b,
                  double axial_b);

class PrbmAssembly;
struct GeneralPrbmPoint;

// The joints' positions and reactions and the ground's reaction through the joints, the springs
// and the assembled flexures, at coordinates q and multipliers mu (scaled, the assembly's), into
// `point`; with `assembled_flexures`, every flexure's PRBM end loads, end stresses and PRB linkage
// too (the PRBM; the exact model fills its flexures itself and adds their loads on the ground).
void fill_point_results(const GeneralMechanism& mechanism,
                        const PrbmAssembly& assembly,
                        const Eigen::VectorXd& q,
                        const Eigen::VectorXd& mu,
                        bool assembled_flexures,
                        GeneralPrbmPoint& point);

// Adds to `ground` (the load the ground puts on the mechanism, moment about the origin) the
// opposite of `load` (what a flexure puts on the ground at the point (x, y)).
void add_ground_reaction(PointLoad& ground, const PointLoad& load, double x, double y);

}  // namespace flexure::mechanism::general
