#include <cmath>

#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/prbm_assembly.h"

namespace flexure::mechanism::general {

FibreStresses fibre_stresses(const Flexure& flexure, double moment, double axial) {
  return fibre_stresses(flexure.width, flexure.thickness, moment, axial);
}

FibreStresses fibre_stresses(double b, double h, double moment, double axial) {
  // A rectangle b x h: A = b h, I/c = b h^2/6 (Howell eqs. 5.22-5.23: sigma = -+ M c/I + N/A).
  const double area = b * h;
  const double modulus = b * h * h / 6.0;
  return {axial / area - moment / modulus, axial / area + moment / modulus};
}

void keep_most_stressed(
    FlexurePointResult& r, const Flexure& flexure, double s, double m, double axial, bool first) {
  keep_most_stressed(r, flexure.width, flexure.thickness, s, m, axial, first);
}

void keep_most_stressed(FlexurePointResult& r,
                        double width,
                        double thickness,
                        double s,
                        double m,
                        double axial,
                        bool first) {
  const FibreStresses st = fibre_stresses(width, thickness, m, axial);
  const double largest = std::max(std::fabs(st.pos), std::fabs(st.neg));
  if (!first && !(largest > r.max_stress)) return;
  r.max_stress = largest;
  r.max_stress_at = s;
  r.max_stress_fibre = std::fabs(st.pos) >= std::fabs(st.neg) ? 1 : -1;
  r.stress_pos_fibre = st.pos;
  r.stress_neg_fibre = st.neg;
  r.moment = m;
  r.axial_force = axial;
}

void end_stresses(FlexurePointResult& r,
                  const Flexure& flexure,
                  double length,
                  double m_a,
                  double axial_a,
                  double m_b,
                  double axial_b) {
  r.max_from = "ends";
  keep_most_stressed(r, flexure, 0.0, m_a, axial_a, true);
  keep_most_stressed(r, flexure, length, m_b, axial_b, false);
}

void add_ground_reaction(PointLoad& ground, const PointLoad& load, double x, double y) {
  ground.fx -= load.fx;
  ground.fy -= load.fy;
  ground.moment -= load.moment + x * load.fy - y * load.fx;
}

void fill_point_results(const GeneralMechanism& mechanism,
                        const PrbmAssembly& A,
                        const Eigen::VectorXd& q,
                        const Eigen::VectorXd& mu,
                        bool assembled_flexures,
                        GeneralPrbmPoint& point) {
  for (std::size_t j = 0; j < mechanism.joints.size(); ++j) {
    const Vec2 p = A.point_position_si(q, mechanism.joints[j].b);
    const Eigen::Vector3d w = A.joint_reaction_si(q, mu, static_cast<int>(j));
    point.joints.push_back({p.x, p.y, {w[0], w[1], w[2]}});
  }
  const Eigen::Vector3d g = A.ground_reaction_si(q, mu);
  point.ground_reaction = {g[0], g[1], g[2]};
  if (!assembled_flexures) return;
  for (std::size_t i = 0; i < mechanism.flexures.size(); ++i) {
    const Flexure& f = mechanism.flexures[i];
    const int fi = static_cast<int>(i);
    FlexurePointResult r;
    const Eigen::Vector3d wa = A.flexure_end_load_si(q, mu, fi, 0);
    const Eigen::Vector3d wb = A.flexure_end_load_si(q, mu, fi, 1);
    r.on_a = {wa[0], wa[1], wa[2]};
    r.on_b = {wb[0], wb[1], wb[2]};
    // Howell's characteristic-radius model carries the load P = -(its load on body b) through
    // its links (no distributed load), so the bending moment at end a is the moment it puts on
    // body a and at end b the opposite of the one on body b (m(s) the moment the part beyond s
    // puts on the part before it; Howell eq. 5.21 at the clamp: M = P (a + n b) for a fixed-
    // pinned segment), and the axial force at each end is P along that end's tangent (eqs.
    // 5.22-5.23).
    const double ta = A.flexure_end_angle(q, fi, 0), tb = A.flexure_end_angle(q, fi, 1);
    const double Px = -wb[0], Py = -wb[1];
    const double axial_a = Px * std::cos(ta) + Py * std::sin(ta);
    const double axial_b = Px * std::cos(tb) + Py * std::sin(tb);
    const Vec2 pa = mechanism.point(f.a), pb = mechanism.point(f.b);
    const double length = f.arc_length(std::hypot(pb.x - pa.x, pb.y - pa.y));
    end_stresses(r, f, length, wa[2], axial_a, -wb[2], axial_b);
    for (const Vec2& p : A.flexure_prb_points_si(q, fi)) {
      r.shape_x.push_back(p.x);
      r.shape_y.push_back(p.y);
    }
    point.flexures.push_back(std::move(r));
  }
}

}  // namespace flexure::mechanism::general
