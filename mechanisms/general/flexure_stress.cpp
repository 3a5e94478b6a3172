#include "flexure/mechanisms/general/flexure_stress.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/prbm_assembly.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/segment_moments.h"
#include "flexure/solver/shooting/shooting_problem.h"

namespace flexure::mechanism::general {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

Eigen::Vector2d vec(const Vec2& v) { return {v.x, v.y}; }

// sigma = |M| c/I + |P|/A of a rectangular b x h section: the fibre stresses of
// general_analysis.h with the moment and the force both counted positive (the catalogue's
// rule adds the magnitudes whatever the force's direction).
double section_stress(const Flexure& f, double moment, double force) {
  const FibreStresses st = fibre_stresses(f, std::abs(moment), std::abs(force));
  return std::max(std::abs(st.pos), std::abs(st.neg));
}

GeneralFlexureStresses empty_stresses(const GeneralMechanism& m, std::size_t points) {
  GeneralFlexureStresses s;
  for (const Flexure& f : m.flexures) {
    s.names.push_back(f.name);
    s.stress.emplace_back();
    s.stress.back().reserve(points);
  }
  s.max_stress.assign(m.flexures.size(), 0.0);
  s.max_force.assign(m.flexures.size(), 0.0);
  return s;
}

void add(GeneralFlexureStresses& s, std::size_t i, double stress, double force) {
  s.stress[i].push_back(stress);
  s.max_stress[i] = std::max(s.max_stress[i], stress);
  s.max_force[i] = std::max(s.max_force[i], std::abs(force));
}

}  // namespace

PrbmPointStatics prbm_point_statics(const GeneralMechanism& m, const GeneralPrbmPoint& p) {
  for (const Flexure& f : m.flexures) {
    if (f.prbm == PrbmKind::kFixedGuided) {
      throw InvalidInput("flexure '" + f.name +
                         "': the PRBM loads of a fixed-guided flexure are not computed");
    }
  }
  const PrbmAssembly A(m);
  const int nd = A.described_body_count();
  if (p.body_x.size() != static_cast<std::size_t>(nd)) {
    throw InvalidInput("prbm_point_statics: the point does not carry the poses of the bodies of '" +
                       m.name + "'");
  }
  const double L = A.length_scale();
  const double force_si = A.energy_scale() / L;  // a multiplier of a scaled pin, in N
  Eigen::VectorXd q = Eigen::VectorXd::Zero(A.coordinate_count());
  for (int b = 0; b < nd; ++b) {
    q[3 * b] = p.body_x[static_cast<std::size_t>(b)] / L;
    q[3 * b + 1] = p.body_y[static_cast<std::size_t>(b)] / L;
    q[3 * b + 2] = p.body_phi[static_cast<std::size_t>(b)];
  }
  // Where a material point (scaled, described configuration) of a body is at q: through a named
  // point of the body and its rotation.
  auto current = [&](const std::string& body, const Eigen::Vector2d& r) -> Eigen::Vector2d {
    if (body == "ground") return r;
    const Body* b = m.find_body(body);
    const PointRef named{body, b->points.front().name};
    const Eigen::Vector2d p0 = vec(b->points.front().position) / L;
    return A.point_scaled(q, named) + Eigen::Rotation2Dd(A.body_rotation(q, body)) * (r - p0);
  };
  // The hidden PRB link of each fixed-pinned flexure (prbm_assembly.h): from its pivot on body a
  // to the pinned end on body b, its reference point their midpoint.
  int hidden = nd;
  for (const Flexure& f : m.flexures) {
    if (f.prbm != PrbmKind::kFixedPinned) continue;
    const Eigen::Vector2d a = vec(m.point(f.a)) / L, b = vec(m.point(f.b)) / L;
    const Eigen::Vector2d pivot = a + howell_average_fixed_pinned().geometry().pivot_x * (b - a);
    const Eigen::Vector2d p1 = current(f.a.body, pivot), p2 = current(f.b.body, b);
    const Eigen::Vector2d rest = b - pivot, now = p2 - p1;
    q.segment<2>(3 * hidden) = (p1 + p2) / 2.0 - (pivot + b) / 2.0;
    // The turn from rest to now, in (-pi, pi] (a difference of atan2s would wrap by 2 pi).
    q[3 * hidden + 2] = std::atan2(cross(rest, now), rest.dot(now));
    ++hidden;
  }
  // The multipliers: J_g^T mu = grad V - lambda grad c (general_analysis.h), least squares. The
  // constraint force on the coordinates is J_g^T mu: a pin g = p_b - p_a pushes its b side with
  // +mu.
  const double lambda = A.load_scaled(p.input_load);
  const Eigen::VectorXd rhs = A.energy_gradient(q) - lambda * A.input_gradient(q);
  const Eigen::MatrixXd Jt = A.constraint_jacobian(q).transpose();
  const Eigen::VectorXd mu = Jt.colPivHouseholderQr().solve(rhs);
  PrbmPointStatics out;
  out.multipliers.assign(mu.data(), mu.data() + mu.size());
  const std::vector<std::string>& items = A.constraint_items();
  for (const Flexure& f : m.flexures) {
    const std::string item = "flexure '" + f.name + "'";
    std::vector<int> rows;
    for (std::size_t k = 0; k < items.size(); ++k) {
      if (items[k] == item) rows.push_back(static_cast<int>(k));
    }
    // The pin at the tip's side: the pivot's pin (small-length, b side on body b) or the pinned
    // end's (fixed-pinned, its second pin). Body b pushes the tip with -mu.
    const int r0 = f.prbm == PrbmKind::kFixedPinned ? rows.at(2) : rows.at(0);
    const Eigen::Vector2d N(-mu[r0] * force_si, -mu[r0 + 1] * force_si);
    const Eigen::Vector2d a = vec(m.point(f.a)) / L, b = vec(m.point(f.b)) / L;
    const double l = (b - a).norm() * L;
    const Eigen::Vector2d root = current(f.a.body, a) * L;
    const Eigen::Vector2d tip = current(f.b.body, b) * L;
    PrbmFlexureLoads w;
    w.Nx = N.x();
    w.Ny = N.y();
    w.tip_dx = tip.x() - root.x();
    w.tip_dy = tip.y() - root.y();
    if (f.prbm == PrbmKind::kSmallLengthPivot) {
      // m at the mid-length pivot is the spring's K psi (Howell eq. 5.14); the pivot is l/2 along
      // the root body from the root: m0 = m(pivot) + r_pivot x N.
      const double phi_a = A.body_rotation(q, f.a.body);
      const double psi = A.body_rotation(q, f.b.body) - phi_a;
      w.stress_moment = f.flexural_rigidity() / l * psi;
      const Eigen::Vector2d r_pivot =
          Eigen::Rotation2Dd(phi_a) * ((b - a) / (b - a).norm()) * (l / 2);
      w.root_moment = w.stress_moment + cross(r_pivot, N);
    } else {
      // Pinned tip (m = 0 there): the clamp moment r_tip x N, the catalogue's M_clamp.
      w.root_moment = cross(tip - root, N);
      w.stress_moment = w.root_moment;
    }
    out.flexures.push_back(w);
  }
  return out;
}

GeneralFlexureStresses prbm_flexure_stresses(const GeneralMechanism& m,
                                             const GeneralPrbmResult& result) {
  const PrbmAssembly A(m);
  const std::vector<std::string> names = A.body_names();
  const std::size_t nd = static_cast<std::size_t>(A.described_body_count());
  if (result.body_names.size() != nd ||
      !std::equal(result.body_names.begin(), result.body_names.end(), names.begin())) {
    throw InvalidInput("prbm_flexure_stresses: the result's bodies are not those of '" + m.name +
                       "'");
  }
  GeneralFlexureStresses s = empty_stresses(m, result.points.size());
  for (const GeneralPrbmPoint& p : result.points) {
    const PrbmPointStatics st = prbm_point_statics(m, p);
    for (std::size_t i = 0; i < m.flexures.size(); ++i) {
      const PrbmFlexureLoads& w = st.flexures[i];
      const double P = std::hypot(w.Nx, w.Ny);
      add(s, i, section_stress(m.flexures[i], w.stress_moment, P), P);
    }
  }
  return s;
}

GeneralFlexureStresses exact_flexure_stresses(const GeneralMechanism& m,
                                              const GeneralPrbmResult& result) {
  if (result.flexure_models.size() != m.flexures.size()) {
    throw InvalidInput(
        "exact_flexure_stresses: the result carries no loads per flexure (solve it with "
        "solve_general_mixed, every flexure exact)");
  }
  GeneralFlexureStresses s = empty_stresses(m, result.points.size());
  ShootingSolver::Options so = ExactMechanismSolver::Options{}.shooting;
  so.rtol = 1e-13;
  so.atol = 1e-15;
  ElasticaIntegrator integrator(so.integrator_options());
  for (std::size_t i = 0; i < m.flexures.size(); ++i) {
    const Flexure& f = m.flexures[i];
    const FlexureModelReport& report = result.flexure_models[i];
    if (report.model != FlexureModel::kExact || f.extensible) {
      throw InvalidInput("exact_flexure_stresses: flexure '" + f.name +
                         "' is not an inextensible exact elastica in this result");
    }
    if (report.loads.size() != result.points.size() || report.tips.size() != result.points.size()) {
      throw InvalidInput("exact_flexure_stresses: flexure '" + f.name +
                         "' has no loads at every point");
    }
    const Vec2 pa = m.point(f.a), pb = m.point(f.b);
    const double l = std::hypot(pb.x - pa.x, pb.y - pa.y);
    const double EI = f.flexural_rigidity();
    // The flexure alone, nondimensional (l = 1, EI = 1), both ends held: its root loads are the
    // shooting unknowns (m0, Nx, Ny), so one integration gives its moments.
    SegmentChain chain;
    chain.segments.push_back(FlexibleSegment{1.0, 1.0});
    chain.end = EndCondition::kFixed;
    for (std::size_t k = 0; k < report.loads.size(); ++k) {
      const FlexureTipLoad& w = report.loads[k];
      const FlexureTip& t = report.tips[k];
      // m(s) = m0 + Nx y(s) - Ny x(s): the root moment from the tip moment and the tip.
      const double m0 = w.mu - w.Fx * t.y + w.Fy * t.x;
      const ShootingProblem problem(chain);
      const Eigen::VectorXd root = Eigen::Vector3d(m0, w.Fx, w.Fy);
      Eigen::VectorXd z = root;
      std::string error;
      if (problem.size() != 3 && !problem.complete_guess(root, 1.0, integrator, z, error)) {
        throw NoConvergence("flexure '" + f.name + "': " + error);
      }
      std::vector<SegmentMoments> moments;
      if (!segment_moments(problem, z, 1.0, integrator, moments, error)) {
        throw NoConvergence("flexure '" + f.name + "': its moments could not be integrated (" +
                            error + ")");
      }
      const double N = std::hypot(w.Fx, w.Fy) * EI / (l * l);
      add(s, i, section_stress(f, moments.front().max_abs_moment * EI / l, N), N);
    }
  }
  return s;
}

}  // namespace flexure::mechanism::general
