#include "flexure/solver/shooting/shooting_problem.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <utility>

#include "flexure/solver/common/status.h"

namespace flexure {

namespace {

// Stress-free pose a distance s along a flexible segment that starts at `p` (a kappa0 arc).
Eigen::Vector4d unloaded_along(const ChainPose& p, double kappa0, double s) {
  const double turn = kappa0 * s;
  const double half = 0.5 * turn;
  const double sinc = std::abs(half) < 1e-4 ? 1.0 - half * half / 6.0 : std::sin(half) / half;
  const double mean = p.theta + half;
  return Eigen::Vector4d(
      p.x + s * sinc * std::cos(mean), p.y + s * sinc * std::sin(mean), p.theta + turn, 0.0);
}

// Total dead load of a flexible segment (its resultant over the whole length).
Eigen::Vector2d dead_resultant(const FlexibleSegment& f) {
  if (!f.has_dead_load()) return Eigen::Vector2d::Zero();
  const std::array<double, 2> Q = f.q_resultant(f.length);
  return Eigen::Vector2d(Q[0], Q[1]);
}

double min_EI(const FlexibleSegment& f) {
  if (f.EI_profile.empty()) return f.EI;
  return *std::min_element(f.EI_profile.begin(), f.EI_profile.end());
}

}  // namespace

ShootingProblem::ShootingProblem(const SegmentChain& chain,
                                 MultipleShootingOptions options,
                                 Homotopy homotopy)
    : chain_(chain), homotopy_(homotopy) {
  chain_.validate();
  mask_ = homotopy_.mask.value_or(prescribed_mask(chain_.end));
  const PrescribedMask full = prescribed_mask(chain_.end);
  // A coordinate the homotopy prescribes beyond the end condition takes the place of its given
  // tip load, which must then be zero (segment_chain.h: the load is the support's reaction).
  const std::pair<bool, double> added[] = {{mask_.x && !full.x, chain_.tip_load.Fx},
                                           {mask_.y && !full.y, chain_.tip_load.Fy},
                                           {mask_.theta && !full.theta, chain_.tip_load.M}};
  const char* names[] = {"x (its tip force Fx", "y (its tip force Fy", "angle (its tip moment M"};
  for (int i = 0; i < 3; ++i) {
    if (added[i].first && added[i].second != 0.0) {
      throw InvalidInput(fmt::format(
          "a controlled tip {}) must be 0 (got {:g}): it is the reaction of the support that "
          "moves the tip",
          names[i],
          added[i].second));
    }
  }
  tip_unloaded_ = chain_.unloaded_tip();
  tip_start_ = homotopy_.tip_start.value_or(tip_unloaded_);
  tip_target_ = homotopy_.tip_target.value_or(chain_.prescribed_tip());
  // A follower force or pressure depends on the deflected shape: both force components are shot.
  const bool follower = chain_.tip_load.follower != 0.0 || chain_.has_follower_pressure();
  unknown_names_.push_back("m0");
  if (mask_.x || follower) {
    index_Nx_ = size();
    unknown_names_.push_back("Nx0");
  }
  if (mask_.y || follower) {
    index_Ny_ = size();
    unknown_names_.push_back("Ny0");
  }
  root_count_ = size();
  node_force_sum_.setZero();
  double force_scale =
      std::hypot(chain_.tip_load.Fx, chain_.tip_load.Fy) + std::abs(chain_.tip_load.follower);
  for (const NodeLoad& load : chain_.node_loads) {
    node_force_sum_ += Eigen::Vector2d(load.Fx, load.Fy);
    force_scale += std::hypot(load.Fx, load.Fy);
  }
  // Distributed loads: their resultants join the dead force sum (N(0) where not shot), and their
  // magnitudes the scale that sets the multiple-shooting cuts.
  segment_dead_load_.assign(chain_.segment_count(), Eigen::Vector2d::Zero());
  for (int j = 0; j < chain_.segment_count(); ++j) {
    const auto* f = std::get_if<FlexibleSegment>(&chain_.segments[j]);
    if (f == nullptr) continue;
    segment_dead_load_[j] = dead_resultant(*f);
    node_force_sum_ += segment_dead_load_[j];
    double magnitude = std::hypot(f->qx, f->qy) * f->length;
    for (const auto& q : f->q_profile) {
      magnitude = std::max(magnitude, std::hypot(q[0], q[1]) * f->length);
    }
    force_scale += magnitude + std::abs(f->q_follower) * f->length;
  }
  // A follower pressure's resultant depends on the shape from the clamp on (the integrator
  // accumulates it), so such a chain is shot from the clamp in one interval (no cuts).
  const bool single_interval = chain_.has_follower_pressure();
  tip_dead_force_ = Eigen::Vector2d(chain_.tip_load.Fx, chain_.tip_load.Fy);

  // Cut the flexible segments so that no part amplifies errors by more than e^budget.
  const std::vector<ChainPose> nodes = chain_.unloaded_nodes();
  const int n = chain_.segment_count();
  std::vector<IntegrationPiece> current;
  double s_global = 0.0;
  for (int j = 0; j < n; ++j) {
    if (const auto* flex = std::get_if<FlexibleSegment>(&chain_.segments[j])) {
      const double growth = flex->length * std::sqrt(force_scale / min_EI(*flex));
      // Clamp as a double first: an extreme load (or a NaN that validation missed) must not
      // overflow the int conversion.
      const double lower = std::max(1, options.min_parts_per_segment);
      const double upper = std::max(1, options.max_parts_per_segment);
      const double wanted = std::ceil(growth / options.amplification_budget);
      const int parts =
          single_interval
              ? 1
              : static_cast<int>(std::isfinite(wanted) ? std::clamp(wanted, lower, upper) : upper);
      for (int p = 0; p < parts; ++p) {
        IntegrationPiece piece;
        piece.segment = j;
        piece.begin = flex->length * p / parts;
        piece.end = (p + 1 == parts) ? flex->length : flex->length * (p + 1) / parts;
        piece.segment_start = s_global;
        piece.crosses_far_node = (p + 1 == parts);
        current.push_back(piece);
        if (p + 1 < parts) {
          intervals_.push_back(std::move(current));
          current.clear();
          unloaded_cut_states_.push_back(unloaded_along(nodes[j], flex->kappa0, piece.end));
        }
      }
      s_global += flex->length;
    } else {
      const auto& rigid = std::get<RigidSegment>(chain_.segments[j]);
      current.push_back(IntegrationPiece{j, 0.0, rigid.length, s_global, true});
      s_global += rigid.length;
    }
  }
  intervals_.push_back(std::move(current));
  for (std::size_t k = 0; k < unloaded_cut_states_.size(); ++k) {
    for (const char* name : {"x", "y", "theta", "m"}) {
      unknown_names_.push_back(fmt::format("{}_cut{}", name, k + 1));
    }
  }
}

ChainForces ShootingProblem::forces(const Eigen::VectorXd& z, double lambda) const {
  const int n = chain_.segment_count();
  ChainForces f;
  f.m0 = z[0];
  // Where a component is not shot for, N(0) is the sum of the given dead loads (free-body diagram
  // of the whole chain, Howell eqs. 7.2-7.3 summed from the root).
  const double lf = load_factor(lambda);
  Eigen::Vector2d N0 = lf * (tip_dead_force_ + node_force_sum_);
  if (index_Nx_ >= 0) N0.x() = z[index_Nx_];
  if (index_Ny_ >= 0) N0.y() = z[index_Ny_];
  f.N.assign(n, N0);
  f.moment_drop.assign(n + 1, 0.0);
  f.load_factor = lf;
  for (const NodeLoad& load : chain_.node_loads) {
    // Node k is the far end of segment k-1: segments k..n-1 no longer carry its force.
    for (int j = load.node; j < n; ++j) f.N[j] -= lf * Eigen::Vector2d(load.Fx, load.Fy);
    f.moment_drop[load.node] += lf * load.M;
  }
  // N[j] is N at the near end of segment j: the dead loads of the segments before it are gone.
  for (int k = 0; k < n; ++k) {
    if (segment_dead_load_[k].isZero()) continue;
    for (int j = k + 1; j < n; ++j) f.N[j] -= lf * segment_dead_load_[k];
  }
  return f;
}

Reaction ShootingProblem::reaction(const Eigen::VectorXd& z, double lambda) const {
  const ChainForces f = forces(z, lambda);
  return Reaction{-f.N[0].x(), -f.N[0].y(), -f.m0};
}

Eigen::VectorXd ShootingProblem::unloaded_unknowns() const {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(size());
  for (std::size_t k = 0; k < unloaded_cut_states_.size(); ++k) {
    z.segment(root_count_ + 4 * k, 4) = unloaded_cut_states_[k];
  }
  return z;
}

Eigen::Vector4d ShootingProblem::interval_start(const Eigen::VectorXd& z, int k) const {
  if (k == 0) return Eigen::Vector4d(0.0, 0.0, 0.0, z[0]);
  return z.segment(root_count_ + 4 * (k - 1), 4);
}

bool ShootingProblem::complete_guess(const Eigen::VectorXd& root_unknowns,
                                     double lambda,
                                     ElasticaIntegrator& integrator,
                                     Eigen::VectorXd& z,
                                     std::string& error) const {
  z = unloaded_unknowns();
  z.head(root_count_) = root_unknowns.head(root_count_);
  const ChainForces f = forces(z, lambda);
  Eigen::Vector4d state = interval_start(z, 0);
  const Eigen::Matrix<double, 4, Eigen::Dynamic> none(4, 0);
  for (int k = 0; k + 1 < interval_count(); ++k) {
    TipState end;
    if (!integrator.integrate(chain_, intervals_[k], f, {}, state, none, end, error)) return false;
    state = Eigen::Vector4d(end.x, end.y, end.theta, end.m);
    z.segment(root_count_ + 4 * k, 4) = state;
  }
  return true;
}

bool ShootingProblem::integrate_solution(const Eigen::VectorXd& z,
                                         double lambda,
                                         ElasticaIntegrator& integrator,
                                         TipState& tip,
                                         std::string& error,
                                         const std::vector<double>* s,
                                         std::vector<ShapePoint>* shape) const {
  const ChainForces f = forces(z, lambda);
  const Eigen::Matrix<double, 4, Eigen::Dynamic> none(4, 0);
  const int M = interval_count();
  for (int k = 0; k < M; ++k) {
    if (!integrator.integrate(chain_,
                              intervals_[k],
                              f,
                              {},
                              interval_start(z, k),
                              none,
                              tip,
                              error,
                              s,
                              shape,
                              k + 1 == M)) {
      return false;
    }
  }
  return true;
}

bool ShootingProblem::evaluate(const Eigen::VectorXd& z,
                               double lambda,
                               bool want_jacobian,
                               bool want_lambda_derivative,
                               ElasticaIntegrator& integrator,
                               ShootingEvaluation& out) const {
  const int n = chain_.segment_count();
  const int nz = size();
  const int M = interval_count();
  const ChainForces f = forces(z, lambda);

  // Sensitivity columns of one interval: its free start-state components, then the shot force
  // components, then lambda. At the clamp only m(0) is free. At a cut, x and y need no columns:
  // the elastica does not depend on where it starts (x, y enter no right-hand side, nor a rigid
  // link or a node load), so d(end)/d(x, y at the cut) is the unit vector of x or y; theta and m
  // get a column each.
  std::vector<ForceDerivative> force_derivs;
  force_derivs.reserve(3);      // Nx, Ny, lambda
  std::vector<int> force_cols;  // global column of each force sensitivity
  if (want_jacobian) {
    for (int idx : {index_Nx_, index_Ny_}) {
      if (idx < 0) continue;
      ForceDerivative d;
      d.dN.assign(n, idx == index_Nx_ ? Eigen::Vector2d(1.0, 0.0) : Eigen::Vector2d(0.0, 1.0));
      force_derivs.push_back(std::move(d));
      force_cols.push_back(idx);
    }
  }
  if (want_lambda_derivative) {
    ForceDerivative d;
    const double slope = homotopy_.load_slope;
    Eigen::Vector2d dN0 = slope * (tip_dead_force_ + node_force_sum_);
    if (index_Nx_ >= 0) dN0.x() = 0.0;
    if (index_Ny_ >= 0) dN0.y() = 0.0;
    d.dN.assign(n, dN0);
    d.dmoment_drop.assign(n + 1, 0.0);
    for (const NodeLoad& load : chain_.node_loads) {
      for (int j = load.node; j < n; ++j) d.dN[j] -= slope * Eigen::Vector2d(load.Fx, load.Fy);
      d.dmoment_drop[load.node] += slope * load.M;
    }
    for (int k = 0; k < n; ++k) {
      for (int j = k + 1; j < n; ++j) d.dN[j] -= slope * segment_dead_load_[k];
    }
    d.dload_factor = slope;
    force_derivs.push_back(std::move(d));
  }
  // Columns of the clamp's interval (index 0) and of a cut's: the start columns, then the rest.
  struct Columns {
    int start = 0;  // start-state columns
    std::vector<ForceDerivative> derivs;
    Eigen::Matrix<double, 4, Eigen::Dynamic> start_sens;
  };
  // `last_use`: force_derivs is not needed after this call, so its vectors are moved, not copied.
  const auto columns = [&](int free_start, bool last_use) {
    Columns c;
    c.start = want_jacobian ? free_start : 0;
    c.derivs.reserve(c.start + force_derivs.size());
    c.derivs.resize(c.start);
    if (last_use) {
      c.derivs.insert(c.derivs.end(),
                      std::make_move_iterator(force_derivs.begin()),
                      std::make_move_iterator(force_derivs.end()));
    } else {
      c.derivs.insert(c.derivs.end(), force_derivs.begin(), force_derivs.end());
    }
    const int Ns = static_cast<int>(c.derivs.size());
    c.start_sens = Eigen::Matrix<double, 4, Eigen::Dynamic>::Zero(4, Ns);
    if (c.start == 1) c.start_sens(3, 0) = 1.0;  // m
    if (c.start == 2) {
      c.start_sens(2, 0) = 1.0;  // theta
      c.start_sens(3, 1) = 1.0;  // m
    }
    return c;
  };
  const Columns at_cut = M > 1 ? columns(2, false) : Columns{};
  const Columns at_clamp = columns(1, true);

  out.residual.setZero(nz);
  if (want_jacobian) out.jacobian.setZero(nz, nz);
  if (want_lambda_derivative) out.d_lambda.setZero(nz);

  Eigen::Matrix<double, 4, Eigen::Dynamic> D(4, nz);  // d(end state)/dz of the current interval
  Eigen::Vector4d D_lambda = Eigen::Vector4d::Zero();
  // d(N at the tip)/dz and /dlambda (the last interval); the force columns' own unit part is in
  // the integrator's N sensitivity.
  Eigen::Matrix<double, 2, Eigen::Dynamic> DN =
      Eigen::Matrix<double, 2, Eigen::Dynamic>::Zero(2, nz);
  Eigen::Vector2d DN_lambda = Eigen::Vector2d::Zero();
  for (int k = 0; k < M; ++k) {
    const Columns& cols = k == 0 ? at_clamp : at_cut;
    TipState end;
    out.ok = integrator.integrate(chain_,
                                  intervals_[k],
                                  f,
                                  cols.derivs,
                                  interval_start(z, k),
                                  cols.start_sens,
                                  end,
                                  out.error);
    if (!out.ok) return false;
    if (want_jacobian) {
      D.setZero();
      if (k == 0) {
        D.col(0) = end.sensitivity.col(0);  // only m(0) is free at the clamp
      } else {
        const int first = root_count_ + 4 * (k - 1);
        D(0, first) = 1.0;  // x at the cut moves the end along x
        D(1, first + 1) = 1.0;
        D.col(first + 2) = end.sensitivity.col(0);
        D.col(first + 3) = end.sensitivity.col(1);
      }
      for (std::size_t c = 0; c < force_cols.size(); ++c) {
        D.col(force_cols[c]) += end.sensitivity.col(cols.start + c);
      }
      if (k + 1 == M) {
        DN.setZero();
        if (k == 0) {
          DN.col(0) = end.N_sensitivity.col(0);
        } else {
          const int first = root_count_ + 4 * (k - 1);
          DN.col(first + 2) = end.N_sensitivity.col(0);
          DN.col(first + 3) = end.N_sensitivity.col(1);
        }
        for (std::size_t c = 0; c < force_cols.size(); ++c) {
          DN.col(force_cols[c]) += end.N_sensitivity.col(cols.start + c);
        }
      }
    }
    const int lam_col = cols.start + static_cast<int>(force_cols.size());
    if (want_lambda_derivative) {
      D_lambda = end.sensitivity.col(lam_col);
      DN_lambda = end.N_sensitivity.col(lam_col);
    }
    const Eigen::Vector4d E(end.x, end.y, end.theta, end.m);
    if (k + 1 < M) {
      const int row = root_count_ + 4 * k;
      out.residual.segment(row, 4) = E - z.segment(row, 4);
      if (want_jacobian) {
        out.jacobian.middleRows(row, 4) = D;
        out.jacobian.block(row, row, 4, 4) -= Eigen::Matrix4d::Identity();
      }
      if (want_lambda_derivative) out.d_lambda.segment(row, 4) = D_lambda;
      continue;
    }
    out.tip = end;
  }

  const TipState& t = out.tip;
  const Eigen::Vector2d N_tip = t.N;
  const double lf = load_factor(lambda);
  const double slope = homotopy_.load_slope;
  const double P = chain_.tip_load.follower;
  const double s_th = std::sin(t.theta), c_th = std::cos(t.theta);

  // theta residual (row 0).
  if (mask_.theta) {
    out.residual[0] =
        t.theta - (tip_start_.theta + lambda * (tip_target_.theta - tip_start_.theta));
    if (want_jacobian) out.jacobian.row(0) = D.row(2);
    if (want_lambda_derivative) {
      out.d_lambda[0] = D_lambda[2] - (tip_target_.theta - tip_start_.theta);
    }
  } else {
    out.residual[0] = t.m - lf * chain_.tip_load.M;
    if (want_jacobian) out.jacobian.row(0) = D.row(3);
    if (want_lambda_derivative) out.d_lambda[0] = D_lambda[3] - slope * chain_.tip_load.M;
  }

  // x and y residuals.
  for (int axis = 0; axis < 2; ++axis) {
    const int row = axis == 0 ? index_Nx_ : index_Ny_;
    if (row < 0) continue;
    const bool prescribed = axis == 0 ? mask_.x : mask_.y;
    if (prescribed) {
      const double start = axis == 0 ? tip_start_.x : tip_start_.y;
      const double target = axis == 0 ? tip_target_.x : tip_target_.y;
      const double value = axis == 0 ? t.x : t.y;
      out.residual[row] = value - (start + lambda * (target - start));
      if (want_jacobian) out.jacobian.row(row) = D.row(axis);
      if (want_lambda_derivative) out.d_lambda[row] = D_lambda[axis] - (target - start);
    } else {
      // Force balance at the tip with the follower force P (-sin theta, cos theta).
      const double follower = axis == 0 ? -P * s_th : P * c_th;
      const double d_follower_dtheta = axis == 0 ? -P * c_th : -P * s_th;
      const double dead = axis == 0 ? tip_dead_force_.x() : tip_dead_force_.y();
      out.residual[row] = N_tip[axis] - lf * (dead + follower);
      if (want_jacobian) out.jacobian.row(row) = DN.row(axis) - lf * d_follower_dtheta * D.row(2);
      if (want_lambda_derivative) {
        out.d_lambda[row] =
            DN_lambda[axis] - slope * (dead + follower) - lf * d_follower_dtheta * D_lambda[2];
      }
    }
  }
  if (!out.residual.allFinite()) {
    out.ok = false;
    out.error = "the shooting residual is not finite";
    return false;
  }
  return true;
}

}  // namespace flexure
