#include "flexure/mechanisms/general/general_exact.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "flexure/mechanisms/general/prbm_assembly.h"
#include "flexure/solver/common/errors.h"
#include "flexure/solver/shooting/elastica_integrator.h"

namespace flexure::mechanism::general {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Shape samples of each flexure for its strain energy at a recorded point (trapezoidal rule on
// m^2/(2 EI): relative error about 1e-5).
constexpr int kEnergySamples = 257;
// Forward-difference step of the Jacobian, scaled coordinates (lengths / size, rad).
constexpr double kJacobianStep = 1e-7;

std::string fmt(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

// One flexure as an elastica between its bodies, in scaled units (lengths / L, loads by the
// assembly's energy scale K: forces F L/K, moments M/K, EI/(K L)).
struct FlexureBeam {
  const Flexure* flexure = nullptr;
  SegmentChain chain;      // one flexible segment (scaled), for the integrator
  double length = 0.0;     // scaled
  double EI = 0.0;         // scaled
  double direction = 0.0;  // rest angle of the flexure from a to b, rad
  bool pinned_tip = false;
};

// The tip state of a beam integrated from its root loads: x, y, theta, m in the root frame.
struct BeamTip {
  double x = 0.0, y = 0.0, theta = 0.0, m = 0.0;
};

// Mixed formulation: the unknowns are the bodies' coordinates q, the joints' multipliers mu, the
// input load lambda and, per flexure, its root loads w = (m0, Nx, Ny) in its root frame (N the
// constant internal force = the load body b applies to the tip). Each residual integrates every
// flexure once from its root loads (an initial-value problem, elastica_integrator.h); the tip
// conditions are equations. Unlike prescribing the tip and solving for the loads, this stays
// regular at a straight flexure, whose axial force is then a multiplier of its inextensibility.
class ExactSystem {
 public:
  ExactSystem(const GeneralMechanism& m, const PrbmAssembly& a)
      : a_(a),
        N_(a.coordinate_count()),
        m_(a.constraint_count()),
        integrator_(ElasticaIntegrator::Options{}) {
    const double L = a.length_scale();
    for (const Flexure& f : m.flexures) {
      FlexureBeam b;
      b.flexure = &f;
      const Vec2 pa = m.point(f.a);
      const Vec2 pb = m.point(f.b);
      b.length = std::hypot(pb.x - pa.x, pb.y - pa.y) / L;
      b.EI = f.flexural_rigidity() / (a.energy_scale() * L);
      b.direction = std::atan2(pb.y - pa.y, pb.x - pa.x);
      b.pinned_tip = f.prbm == PrbmKind::kFixedPinned;
      b.chain.segments.push_back(FlexibleSegment{b.length, b.EI, {}, 0.0});
      beams_.push_back(b);
    }
  }

  int flexure_offset() const { return N_ + m_ + 1; }
  int size() const { return N_ + m_ + 1 + 3 * static_cast<int>(beams_.size()); }

  // Integrates beam b from root loads w; `shape` (optional) gets the pose at `samples` points.
  bool integrate(const FlexureBeam& b,
                 const Eigen::Vector3d& w,
                 BeamTip& tip,
                 std::vector<ShapePoint>* shape = nullptr,
                 int samples = 0) {
    ChainForces forces;
    forces.m0 = w[0];
    forces.N = {Eigen::Vector2d(w[1], w[2])};
    forces.moment_drop = {0.0, 0.0};
    const std::vector<IntegrationPiece> pieces{IntegrationPiece{0, 0.0, b.length, 0.0, false}};
    std::vector<double> stations;
    for (int i = 0; i < samples; ++i) {
      stations.push_back(b.length * i / (samples - 1));
    }
    TipState end;
    std::string error;
    const Eigen::Matrix<double, 4, Eigen::Dynamic> no_sensitivity(4, 0);
    if (!integrator_.integrate(b.chain,
                               pieces,
                               forces,
                               {},
                               Eigen::Vector4d(0, 0, 0, w[0]),
                               no_sensitivity,
                               end,
                               error,
                               shape != nullptr ? &stations : nullptr,
                               shape)) {
      return false;
    }
    tip = {end.x, end.y, end.theta, end.m};
    return true;
  }

  // Residual at z = (q, mu, lambda, w...) and input s; false when an integration fails.
  bool residual(const VectorXd& z, double s, VectorXd& F) {
    const VectorXd q = z.head(N_);
    F.resize(size());
    VectorXd Q = VectorXd::Zero(N_);
    for (std::size_t i = 0; i < beams_.size(); ++i) {
      const FlexureBeam& b = beams_[i];
      const Flexure& f = *b.flexure;
      const int o = flexure_offset() + 3 * static_cast<int>(i);
      const Eigen::Vector3d w = z.segment<3>(o);
      BeamTip tip;
      if (!integrate(b, w, tip)) {
        return false;
      }
      const double beta = b.direction + a_.body_rotation(q, f.a.body);
      const double c = std::cos(beta), sn = std::sin(beta);
      const Eigen::Vector2d N(c * w[1] - sn * w[2], sn * w[1] + c * w[2]);  // global
      // The beam pushes its root body with +N, +m0 and its tip body with -N, -m(tip).
      a_.add_wrench(q, f.a, N, w[0], Q);
      a_.add_wrench(q, f.b, -N, -tip.m, Q);
      const Eigen::Vector2d d = a_.point_scaled(q, f.b) - a_.point_scaled(q, f.a);
      F[o] = tip.x - (c * d.x() + sn * d.y());
      F[o + 1] = tip.y - (-sn * d.x() + c * d.y());
      F[o + 2] = b.pinned_tip
                     ? tip.m
                     : tip.theta - (a_.body_rotation(q, f.b.body) - a_.body_rotation(q, f.a.body));
    }
    F.head(N_) = a_.lagrangian_gradient(q, z.segment(N_, m_), z[N_ + m_]) - Q;
    F.segment(N_, m_) = a_.constraints(q);
    F[N_ + m_] = a_.input(q) - s;
    return F.allFinite();
  }

  // Damped Newton at input s from z (updated), Jacobian by forward differences.
  bool newton(VectorXd& z, double s, double tolerance, int max_iterations, int* iterations) {
    VectorXd F;
    if (!residual(z, s, F)) {
      return false;
    }
    for (int it = 0; it <= max_iterations; ++it) {
      const double r = F.lpNorm<Eigen::Infinity>();
      if (r < tolerance) {
        residual_ = std::max(residual_, r);
        return true;
      }
      if (it == max_iterations) {
        break;
      }
      ++*iterations;
      MatrixXd J(size(), size());
      for (int j = 0; j < size(); ++j) {
        VectorXd zp = z;
        const double h = kJacobianStep * std::max(1.0, std::fabs(z[j]));
        zp[j] += h;
        VectorXd Fp;
        if (!residual(zp, s, Fp)) {
          return false;
        }
        J.col(j) = (Fp - F) / h;
      }
      const VectorXd dz = J.fullPivLu().solve(-F);
      if (!dz.allFinite()) {
        return false;
      }
      double t = 1.0;
      bool improved = false;
      for (int k = 0; k < 10; ++k) {
        VectorXd zt = z + t * dz;
        VectorXd Ft;
        if (residual(zt, s, Ft) && Ft.lpNorm<Eigen::Infinity>() < r) {
          z = zt;
          F = Ft;
          improved = true;
          break;
        }
        t *= 0.5;
      }
      if (!improved) {
        return false;
      }
    }
    return false;
  }

  // The flexures' strain energy at z (scaled), from their sampled shapes.
  double strain_energy(const VectorXd& z) {
    double U = 0.0;
    for (std::size_t i = 0; i < beams_.size(); ++i) {
      const FlexureBeam& b = beams_[i];
      const Eigen::Vector3d w = z.segment<3>(flexure_offset() + 3 * static_cast<int>(i));
      std::vector<ShapePoint> shape;
      BeamTip tip;
      if (!integrate(b, w, tip, &shape, kEnergySamples) || shape.size() < 2) {
        throw NoConvergence("flexure '" + b.flexure->name + "': its shape could not be sampled");
      }
      // m(s) = m0 + Nx y(s) - Ny x(s) in the beam's frame (m' = Nx sin theta - Ny cos theta).
      for (std::size_t k = 1; k < shape.size(); ++k) {
        const ShapePoint& p0 = shape[k - 1];
        const ShapePoint& p1 = shape[k];
        const double ma = w[0] + w[1] * p0.y - w[2] * p0.x;
        const double mb = w[0] + w[1] * p1.y - w[2] * p1.x;
        U += 0.5 * (ma * ma + mb * mb) / (2.0 * b.EI) * (p1.s - p0.s);
      }
    }
    return U;
  }

  double residual() const { return residual_; }

 private:
  const PrbmAssembly& a_;
  int N_, m_;
  std::vector<FlexureBeam> beams_;
  ElasticaIntegrator integrator_;
  double residual_ = 0.0;
};

Stability exact_not_checked() {
  return not_checked_stability(
      "the exact model of a general mechanism does not judge stability yet");
}

}  // namespace

void GeneralExactOptions::validate() const {
  if (!(tolerance > 0.0) || !(tolerance < 1e-3)) {
    throw InvalidInput("GeneralExactOptions.tolerance must be in (0, 1e-3)");
  }
  if (max_newton_iterations < 1 || max_step_halvings < 0) {
    throw InvalidInput(
        "GeneralExactOptions.max_newton_iterations must be >= 1, max_step_halvings >= 0");
  }
}

GeneralPrbmResult solve_general_exact(const GeneralMechanism& mechanism,
                                      const GeneralExactOptions& options) {
  options.validate();
  mechanism.validate();
  if (mechanism.input.control != InputControl::kDisplacement) {
    throw InvalidInput(mechanism.where(mechanism.input.line) +
                       "input: the exact model of a general mechanism follows displacement "
                       "control only so far");
  }
  const int dof = check_general_mechanism(mechanism);
  const PrbmAssembly A(mechanism, /*assemble_flexures=*/false);
  ExactSystem S(mechanism, A);
  const int N = A.coordinate_count();
  const int m = A.constraint_count();
  GeneralPrbmResult result;
  result.degrees_of_freedom = dof;
  const std::vector<std::string> names = A.body_names();
  result.body_names = names;

  const Input& in = mechanism.input;
  std::vector<double> grid(static_cast<std::size_t>(in.count));
  for (int i = 0; i < in.count; ++i) {
    grid[static_cast<std::size_t>(i)] =
        A.input_scaled(in.start + (in.stop - in.start) * i / (in.count - 1));
  }

  VectorXd z = VectorXd::Zero(S.size());
  int iterations = 0;
  double s = A.input(z.head(N));
  auto fail = [&](const std::string& why) {
    result.termination = Termination::kNoConvergence;
    result.message = why;
    result.iterations = iterations;
    return result;
  };
  if (!in.start_rotation.empty()) {
    for (const auto& [body, angle] : in.start_rotation) {
      const auto it = std::find(names.begin(), names.end(), body);
      z[3 * (it - names.begin()) + 2] = angle;
    }
    s = grid.front();
    if (!S.newton(z, s, options.tolerance, options.max_newton_iterations, &iterations)) {
      return fail(
          "Newton did not converge at the first input value from the given "
          "start_rotation");
    }
  } else if (!S.newton(z, s, options.tolerance, options.max_newton_iterations, &iterations)) {
    return fail("Newton did not converge at the described configuration");
  }

  // Natural-parameter continuation with a secant predictor; the input step is halved on failure.
  VectorXd z_prev = z;
  double s_prev = s;
  auto advance = [&](double target) {
    double step = target - s;
    int halvings = 0;
    while (s != target) {
      const double s_next = std::fabs(target - s) <= std::fabs(step) ? target : s + step;
      VectorXd trial = z;
      if (s != s_prev) {
        trial += (z - z_prev) * ((s_next - s) / (s - s_prev));
      }
      if (S.newton(trial, s_next, options.tolerance, options.max_newton_iterations, &iterations)) {
        z_prev = z;
        s_prev = s;
        z = trial;
        s = s_next;
        continue;
      }
      if (++halvings > options.max_step_halvings) {
        return false;
      }
      step *= 0.5;
    }
    return true;
  };

  auto record = [&]() {
    GeneralPrbmPoint pt;
    const VectorXd q = z.head(N);
    pt.input = A.input_si(s);
    pt.input_load = A.load_si(z[N + m]);
    const double strain = S.strain_energy(z);
    pt.spring_energy = A.energy_si(A.spring_energy(q) + strain);
    pt.energy = A.energy_si(A.energy(q) + strain);
    pt.displacement_control = exact_not_checked();
    pt.force_control = exact_not_checked();
    for (int b = 0; b < A.described_body_count(); ++b) {
      pt.body_x.push_back(q[3 * b] * A.length_scale());
      pt.body_y.push_back(q[3 * b + 1] * A.length_scale());
      pt.body_phi.push_back(q[3 * b + 2]);
    }
    result.points.push_back(std::move(pt));
  };

  std::vector<std::pair<double, VectorXd>> path;  // (s, z) at the grid points
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (!advance(grid[i])) {
      result.iterations = iterations;
      result.termination = Termination::kNoConvergence;
      result.message = "the exact model's continuation failed before input " +
                       fmt(A.input_si(grid[i])) + " (" + std::to_string(result.points.size()) +
                       " of " + std::to_string(in.count) + " points)";
      return result;
    }
    record();
    path.emplace_back(s, z);
  }

  // Equilibria: sign changes of the input load between grid points, refined by the secant
  // method on s (each evaluation a converged point).
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    double s0 = path[i].first, s1 = path[i + 1].first;
    double l0 = path[i].second[N + m], l1 = path[i + 1].second[N + m];
    if (!(l0 * l1 <= 0.0)) {
      continue;
    }
    z = path[i].second;
    s = s0;
    z_prev = z;
    s_prev = s;
    bool ok = true;
    for (int k = 0; k < 60 && std::fabs(s1 - s0) > 1e-13 && l1 != l0; ++k) {
      const double s_new = s1 - l1 * (s1 - s0) / (l1 - l0);
      if (!advance(s_new)) {
        ok = false;
        break;
      }
      s0 = s1;
      l0 = l1;
      s1 = s;
      l1 = z[N + m];
      if (std::fabs(l1) < options.tolerance) {
        break;
      }
    }
    if (!ok) {
      result.warn(WarningKind::kOther,
                  "an exact equilibrium near input " + fmt(A.input_si(path[i].first)) +
                      " was bracketed but not refined");
      continue;
    }
    GeneralEquilibrium e;
    e.input = A.input_si(s);
    e.energy = A.energy_si(A.energy(z.head(N)) + S.strain_energy(z));
    e.stability = exact_not_checked();
    result.equilibria.push_back(std::move(e));
  }
  result.iterations = iterations;
  result.residual = S.residual();
  result.termination = Termination::kConverged;
  return result;
}

}  // namespace flexure::mechanism::general
