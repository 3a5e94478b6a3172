#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/cfm/constant_force.h"
#include "flexure/mechanisms/cfm/slider_crank.h"
#include "flexure/mechanisms/inversion.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

}  // namespace

std::vector<double> stroke_displacements(const MechanismDesign& design, int points) {
  if (points < 2 || points > 100000) {
    throw InvalidInput(fmt::format("points must be in [2, 100000] (got {})", points));
  }
  std::vector<double> dx(points);
  // The last point is the stroke itself: (stroke*K)/K can round one ulp above it, which at a
  // stroke equal to the toggle position (validate --toggle-fraction 1) is past the toggle.
  for (int k = 1; k < points; ++k) dx[k - 1] = design.stroke * k / points;
  dx[points - 1] = design.stroke;
  return dx;
}

PrbmState prbm_state(const MechanismDesign& design, double displacement) {
  const auto& cfg = design.configuration();
  const double R = design.R();
  const double r_tot = design.r2 + design.r3;
  const auto pose = cfm::slider_crank_pose(R, displacement / r_tot);
  const double k1 = design.spring_constant(1), k2 = design.spring_constant(2),
               k3 = design.spring_constant(3);
  PrbmState s;
  s.displacement = displacement;
  s.theta2 = pose.theta2;
  s.theta3 = pose.theta3;
  // Virtual work, thesis eq. 2.14 (principal-angle spring rotations) scaled by eq. 2.13/2.19.
  const bool is_1B = cfg.is_class_1B();
  const double k_ref = is_1B ? k2 : k1;
  const double K1 = is_1B ? 1.0 : k2 / k1, K2 = k3 / k_ref;
  s.force = k_ref / design.r2 * cfm::force_function_phi(R, K1, K2, is_1B, pose);
  // An inversion (slider block fixed) has the same relative motion; its force comes from the
  // general virtual-work formula on the mirrored mechanism (inversion.h), a second code path that
  // the tests compare with the line above.
  if (design.inverted) s.force = inverted_prbm_force(design, displacement);

  // Statics of the PRB links: crank moments about pivot 1, coupler moments about pivot 3, with P
  // the force of the coupler on the crank (springs resist their rotations psi_i).
  const double e2x = std::cos(pose.theta2), e2y = std::sin(pose.theta2);
  const double e3x = std::cos(pose.theta3), e3y = std::sin(pose.theta3);
  const double c1 = k1 * pose.psi1() + k2 * pose.psi2();  // = cross(r2 e2, P)
  const double c2 = k2 * pose.psi2() + k3 * pose.psi3();  // = cross(-r3 e3, P)
  const double ax = design.r2 * e2x, ay = design.r2 * e2y;
  const double bx = -design.r3 * e3x, by = -design.r3 * e3y;
  // Solve [-ay ax; -by bx] P = [c1; c2]; det = cross(a, b) vanishes only when folded flat.
  const double det = ax * by - ay * bx;
  s.pin_force_x = (c1 * bx - ax * c2) / det;
  s.pin_force_y = (-ay * c2 + by * c1) / det;

  const double P = std::hypot(s.pin_force_x, s.pin_force_y);
  const double p2x = ax, p2y = ay, p3x = ax - bx, p3y = ay - by;
  for (int p = 1; p <= 3; ++p) {
    const JointDesign& j = design.joints[p - 1];
    if (j.type == PivotType::kPin) continue;
    const Section section = j.section();  // a rectangle: its area is known
    const double I = section.second_moment(), half_h = 0.5 * j.thickness;
    double M = 0.0;
    if (j.type == PivotType::kSmall) {
      const double psi = p == 1 ? pose.psi1() : p == 2 ? pose.psi2() : pose.psi3();
      // A fixed-fixed strip turned by psi between its two rigid bodies is bent to the curvature
      // psi/L whatever spring rule the force uses: M = (EI/L) psi (pure bending).
      const double K = j.segment == SegmentKind::kFixedFixed
                           ? j.flexural_rigidity(design.material) / j.length
                           : design.spring_constant(p);
      M = K * psi;
    } else {
      // Clamp behind the characteristic pivot: (1 - gamma) l (Howell §5.2).
      const double back = howell_average_fixed_pinned().geometry().pivot_x * j.length;
      double cx, cy, ex, ey;  // clamp, pinned end
      if (p == 1) {
        cx = -back, cy = 0.0, ex = p2x, ey = p2y;
      } else if (cfg.middle_long_on_r2) {  // plp: beam pinned at ground, clamped into link 3
        cx = p2x + back * e3x, cy = p2y + back * e3y, ex = 0.0, ey = 0.0;
      } else {  // slp: beam clamped to link 2, pinned at the slider
        cx = p2x - back * e2x, cy = p2y - back * e2y, ex = p3x, ey = p3y;
      }
      M = cross(ex - cx, ey - cy, s.pin_force_x, s.pin_force_y);
    }
    s.moment[p - 1] = M;
    s.stress[p - 1] = std::abs(M) * half_h / I + P / *section.area();
  }
  return s;
}

PrbmStrokeResult prbm_stroke(const MechanismDesign& design, int points) {
  PrbmStrokeResult r;
  r.set_converged(true);  // closed form: converged unless a value is not finite (below)
  r.displacement = stroke_displacements(design, points);
  r.force.reserve(points);
  for (int p = 0; p < 3; ++p) {
    if (design.joints[p].type != PivotType::kPin) r.stress[p].reserve(points);
  }
  double sum = 0.0;
  for (double dx : r.displacement) {
    const PrbmState s = prbm_state(design, dx);
    if (!std::isfinite(s.force)) {
      r.set_converged(false);
      r.message = fmt::format("PRBM force not finite at Delta x = {:.6g} m", dx);
      return r;
    }
    r.force.push_back(s.force);
    r.residual = std::max(r.residual, std::abs(-s.pin_force_x - s.force) / std::abs(s.force));
    sum += s.force;
    for (int p = 0; p < 3; ++p) {
      if (design.joints[p].type == PivotType::kPin) continue;
      r.stress[p].push_back(s.stress[p]);
      r.max_stress[p] = std::max(r.max_stress[p], s.stress[p]);
    }
    ++r.iterations;
  }
  for (int p = 0; p < 3; ++p) {
    if (r.max_stress[p] > r.max_stress_all) {
      r.max_stress_all = r.max_stress[p];
      r.critical_pivot = p + 1;
    }
  }
  r.safety_factor = design.material.yield_strength.value_or(0.0) / r.max_stress_all;
  r.mean_force = sum / points;
  const ConstantForceMeasure cf = constant_force_measure(r.force);
  r.percent_constant_force = cf.percent;
  r.force_vanishes = cf.vanishes;
  r.force_changes_sign = cf.changes_sign;
  r.message = "closed form";
  return r;
}

}  // namespace flexure::mechanism
