#include "flexure/elements/cbcm_path.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "flexure/elements/chained_bcm_model.h"
#include "flexure/elements/ladder_models.h"
#include "flexure/elements/load_path_newton.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

using detail::cbcm::Discretisation;
using detail::cbcm::Evaluation;
using detail::cbcm::Prepared;
using Eigen::MatrixXd;
using Eigen::VectorXd;

int coordinate_index(TipCoordinate c) {
  return c == TipCoordinate::kX ? 0 : c == TipCoordinate::kY ? 1 : 2;
}

// The moving stage in the unknowns X = (z, lambda): residual, Jacobian, tangent, correctors.
class MovingStage {
 public:
  MovingStage(const Prepared& p, Discretisation& model, double tolerance)
      : p_(p), model_(model), nz_(model.size()), tolerance_(tolerance) {
    // Weights of the arclength: the element displacements and lambda 1, the reactions (up to the
    // axial stiffness d, 1e4 and more for a thin beam) 0.01, so that the geometry sets the step.
    w_ = VectorXd::Ones(nz_ + 1);
    for (int i = 2 * model.elements(); i < nz_; ++i) w_[i] = 0.01;
  }

  int unknowns() const { return nz_ + 1; }
  const VectorXd& weights() const { return w_; }

  bool residual(const VectorXd& X, VectorXd& r) const {
    model_.residual(X.head(nz_), X[nz_], scratch_, r);
    return r.allFinite();
  }

  // dr/dX by forward differences (n_z x (n_z + 1)).
  bool jacobian(const VectorXd& X, const VectorXd& r0, MatrixXd& J) const {
    J.resize(nz_, nz_ + 1);
    VectorXd Xp = X, r;
    for (int k = 0; k <= nz_; ++k) {
      const double step = 1e-7 * std::max(1.0, std::fabs(X[k]));
      Xp[k] = X[k] + step;
      if (!residual(Xp, r)) return false;
      J.col(k) = (r - r0) / step;
      Xp[k] = X[k];
    }
    return true;
  }

  // [J; row'] -- the augmented matrix of the tangent and of the bordered corrector.
  MatrixXd bordered(const MatrixXd& J, const VectorXd& row) const {
    MatrixXd A(nz_ + 1, nz_ + 1);
    A.topRows(nz_) = J;
    A.row(nz_) = row.transpose();
    return A;
  }

  // The unit (weighted) tangent at X, oriented along `previous`; `sign` the sign of det of the
  // augmented Jacobian with the tangent's weighted row (changes at a simple bifurcation).
  bool tangent(const VectorXd& X, const VectorXd& previous, VectorXd& t, int& sign) const {
    VectorXd r;
    MatrixXd J;
    if (!residual(X, r) || !jacobian(X, r, J)) return false;
    const Eigen::PartialPivLU<MatrixXd> lu(bordered(J, w_.cwiseProduct(previous)));
    VectorXd e = VectorXd::Zero(nz_ + 1);
    e[nz_] = 1.0;
    t = lu.solve(e);
    if (!t.allFinite()) return false;
    t /= weighted_norm(t);
    if (weighted_dot(t, previous) < 0.0) t = -t;
    sign = determinant_sign(bordered(J, w_.cwiseProduct(t)));
    return true;
  }

  // The sign of det of the chord-bordered Jacobian at X and the lambda component of the tangent
  // there (for locating bifurcations and folds between two path points).
  bool chord_tests(const VectorXd& X, const VectorXd& chord, int& sign, double& t_lambda) const {
    VectorXd r;
    MatrixXd J;
    if (!residual(X, r) || !jacobian(X, r, J)) return false;
    const MatrixXd A = bordered(J, w_.cwiseProduct(chord));
    sign = determinant_sign(A);
    VectorXd e = VectorXd::Zero(nz_ + 1);
    e[nz_] = 1.0;
    const VectorXd t = A.partialPivLu().solve(e);
    t_lambda = t[nz_];
    return t.allFinite();
  }

  // Newton on [r(X); (w n)'(X - anchor)] = 0 from X (Keller's hyperplane through anchor, normal
  // n). Returns the iterations used, -1 when it failed.
  int correct(VectorXd& X, const VectorXd& normal, const VectorXd& anchor, int max_iterations) {
    const VectorXd row = w_.cwiseProduct(normal);
    VectorXd r;
    MatrixXd J;
    for (int it = 0; it <= max_iterations; ++it) {
      if (!residual(X, r)) return -1;
      const double plane = row.dot(X - anchor);
      if (r.lpNorm<Eigen::Infinity>() <= tolerance_ && std::fabs(plane) <= tolerance_) return it;
      if (it == max_iterations) break;
      if (!jacobian(X, r, J)) return -1;
      VectorXd rhs(nz_ + 1);
      rhs.head(nz_) = -r;
      rhs[nz_] = -plane;
      const VectorXd dX = bordered(J, row).partialPivLu().solve(rhs);
      if (!dX.allFinite()) return -1;
      X += dX;
      ++newton_iterations;
    }
    return -1;
  }

  // Newton with lambda fixed at `lambda` (the end of the path).
  bool correct_at(VectorXd& X, double lambda, int max_iterations) {
    VectorXd normal = VectorXd::Zero(nz_ + 1);
    normal[nz_] = 1.0 / w_[nz_];
    VectorXd anchor = X;
    anchor[nz_] = lambda;
    X[nz_] = lambda;
    return correct(X, normal, anchor, max_iterations) >= 0;
  }

  double weighted_dot(const VectorXd& a, const VectorXd& b) const {
    return a.cwiseProduct(w_).dot(b);
  }
  double weighted_norm(const VectorXd& a) const { return std::sqrt(weighted_dot(a, a)); }

  int newton_iterations = 0;

 private:
  static int determinant_sign(const MatrixXd& A) {
    const Eigen::PartialPivLU<MatrixXd> lu(A);
    double sign = lu.permutationP().determinant();
    const MatrixXd& U = lu.matrixLU();
    for (int i = 0; i < U.rows(); ++i) {
      if (U(i, i) < 0.0) sign = -sign;
      if (U(i, i) == 0.0) return 0;
    }
    return sign > 0.0 ? 1 : -1;
  }

  const Prepared& p_;
  Discretisation& model_;
  int nz_;
  double tolerance_;
  VectorXd w_;
  mutable Evaluation scratch_;
};

// One path row from the state X (the chain's units).
CbcmPathPoint state_of(const Prepared& p,
                       const Discretisation& model,
                       const VectorXd& X,
                       bool moving,
                       int stage,
                       int branch,
                       int status) {
  const int nz = model.size();
  const double lambda = X[nz];
  const double load_factor = moving ? 1.0 : lambda;
  Evaluation e;
  model.evaluate(X.head(nz), load_factor, e);
  const double L = p.L, force_unit = p.EI / (L * L), moment_unit = p.EI / L;
  CbcmPathPoint out;
  out.lambda = lambda;
  out.tip = {e.tip.x * L, e.tip.y * L, e.tip.theta};
  const detail::cbcm::EndLoads loads = detail::cbcm::end_loads(p, e, load_factor);
  out.reaction = {
      -loads.clamp.Fx * force_unit, -loads.clamp.Fy * force_unit, -loads.clamp.M * moment_unit};
  out.tip_load = {loads.tip.Fx * force_unit, loads.tip.Fy * force_unit, loads.tip.M * moment_unit};
  for (int j = 0; j < model.elements(); ++j) {
    out.max_element_deflection = std::max(out.max_element_deflection, std::fabs(X[2 * j]));
  }
  out.status = status;
  out.stage = stage;
  out.branch = branch;
  return out;
}

double conjugate(const CbcmPathPoint& point, int coordinate) {
  return coordinate == 0   ? point.tip_load.Fx
         : coordinate == 1 ? point.tip_load.Fy
                           : point.tip_load.M;
}

double coordinate_of(const CbcmPathPoint& point, int coordinate) {
  return coordinate == 0 ? point.tip.x : coordinate == 1 ? point.tip.y : point.tip.theta;
}

}  // namespace

void CbcmPathOptions::validate() const {
  if (elements < 1 || elements > 2000) {
    throw InvalidInput(
        fmt::format("the chained BCM's number of elements must be 1 to 2000 (got {})", elements));
  }
  if (!std::isfinite(slenderness) || slenderness < 0.0) {
    throw InvalidInput(fmt::format(
        "the slenderness L/t must be 0 (inextensible) or finite and > 0 (got {})", slenderness));
  }
  if (!(max_load_step > 0.0 && max_load_step <= 1.0)) {
    throw InvalidInput(
        fmt::format("the CBCM path's largest load step must be in (0, 1] (got {})", max_load_step));
  }
  if (!(max_angle_step > 0.0 && max_angle_step <= 1.0)) {
    throw InvalidInput(fmt::format(
        "the CBCM path's largest angle step must be in (0, 1] rad (got {})", max_angle_step));
  }
  if (branch < 0) {
    throw InvalidInput(
        fmt::format("--branch counts the bifurcations along the path from 1 (got {})", branch));
  }
  if (branch_side != 1 && branch_side != -1) {
    throw InvalidInput("the branch side is +1 (tip to +y) or -1 (tip to -y)");
  }
  if (!(std::isfinite(tolerance) && tolerance > 0.0) || max_steps < 1) {
    throw InvalidInput("the CBCM path's tolerance must be finite and > 0, max_steps >= 1");
  }
}

CbcmPathResult trace_cbcm_controlled_path(const SegmentChain& chain,
                                          const DisplacementControl& control,
                                          const CbcmPathOptions& options) {
  options.validate();
  const std::string name = options.elements == 1 ? "bcm" : "cbcm";
  if (!std::isfinite(control.target)) {
    throw InvalidInput(fmt::format(
        "the target of {} must be finite (got {})", to_string(control.coordinate), control.target));
  }
  const int coordinate = coordinate_index(control.coordinate);
  const Prepared p = detail::cbcm::prepare(chain, name, coordinate);
  const double d = detail::cbcm::axial_stiffness(p, options.slenderness, name);
  Discretisation model(p, options.elements, 1.0 / d);
  const int nz = model.size();
  const int n = options.elements;

  CbcmPathResult out;
  out.elements = n;
  out.axial_stiffness = d;
  const double scale = coordinate == 2 ? 1.0 : 1.0 / p.L;  // chain units -> per L

  // Stage 1: the loads and the end's prescribed coordinates, by proportional loading.
  VectorXd z = VectorXd::Zero(nz);
  bool loaded = false;
  for (const auto& l : p.distal_loads) loaded = loaded || l.Fx != 0.0 || l.Fy != 0.0 || l.M != 0.0;
  for (const auto& [at, l] : p.root_loads)
    loaded = loaded || l.Fx != 0.0 || l.Fy != 0.0 || l.M != 0.0;
  if (p.mask.x && coordinate != 0) loaded = loaded || p.target.x != p.unloaded.x;
  if (p.mask.y && coordinate != 1) loaded = loaded || p.target.y != p.unloaded.y;
  if (p.mask.theta && coordinate != 2) loaded = loaded || p.target.theta != p.unloaded.theta;
  if (p.controlled_by_end) {
    const double c[3] = {
        p.target.x - p.unloaded.x, p.target.y - p.unloaded.y, p.target.theta - p.unloaded.theta};
    loaded = loaded || c[coordinate] != 0.0;
  }
  int stage = 1;
  if (loaded) {
    Evaluation scratch;
    const auto residual = [&](const VectorXd& state, double lambda, VectorXd& r) {
      model.residual(state, lambda, scratch, r);
      return r.allFinite();
    };
    const detail::MeasureFunction node_angles = [n](const VectorXd& state) -> VectorXd {
      VectorXd angles(n);
      double angle = 0.0;
      for (int j = 0; j < n; ++j) angles[j] = angle += state[2 * j + 1];
      return angles;
    };
    detail::LoadPathOptions path;
    path.tolerance = options.tolerance * p.load_scale;
    const detail::LoadPathOutcome first =
        detail::follow_load_path(z, residual, nullptr, node_angles, path);
    VectorXd X0(nz + 1);
    X0 << VectorXd::Zero(nz), 0.0;
    out.points.push_back(state_of(p, model, X0, false, 1, 0, 0));
    VectorXd X1(nz + 1);
    X1 << z, first.load_factor;
    out.points.push_back(state_of(p, model, X1, false, 1, 0, first.converged ? 3 : 1));
    out.newton_iterations += first.iterations;
    if (!first.converged) {
      out.message = fmt::format(
          "the loads applied before the controlled coordinate moves (stage 1) "
          "could not be followed: {}",
          first.message);
      out.set_converged(false);
      return out;
    }
    stage = 2;
  }

  // Stage 2: the controlled coordinate moves.
  Evaluation e;
  model.evaluate(z, 1.0, e);
  const double start_tip[3] = {e.tip.x, e.tip.y, e.tip.theta};
  const double start = start_tip[coordinate];
  const double end = control.target * scale;
  model.set_moving(start, end);
  MovingStage moving(p, model, options.tolerance * p.load_scale);
  VectorXd X(nz + 1);
  X << z, 0.0;
  {
    // The start: the state of stage 1 with the coordinate's reaction found (it was free there).
    if (!moving.correct_at(X, 0.0, 30)) {
      out.message = "the start of the moving stage could not be converged";
      out.set_converged(false);
      return out;
    }
  }
  int branch = 0;
  out.points.push_back(state_of(p, model, X, true, stage, branch, stage == 1 ? 0 : 1));
  std::vector<VectorXd> states{X};  // the unknowns of every moving-stage row
  std::vector<std::size_t> rows{out.points.size() - 1};
  const int first_row = static_cast<int>(out.points.size()) - 1;

  // Which way the new branch goes at a bifurcation (cbcm_path.h).
  const PrescribedMask end_mask = prescribed_mask(chain.end);
  const bool y_held = end_mask.y || coordinate == 1;
  const bool theta_held = end_mask.theta || coordinate == 2;
  auto side_value = [&](const VectorXd& state) {
    const CbcmPathPoint pt = state_of(p, model, state, true, stage, branch, 1);
    if (!y_held) return pt.tip.y;
    if (!theta_held) return pt.tip.theta;
    return -pt.reaction.M;  // m(0)
  };
  auto node_angles = [n](const VectorXd& state) {
    VectorXd angles(n);
    double angle = 0.0;
    for (int j = 0; j < n; ++j) angles[j] = angle += state[2 * j + 1];
    return angles;
  };

  VectorXd direction = VectorXd::Zero(nz + 1);
  direction[nz] = 1.0;
  VectorXd t;
  int det_sign = 0;
  if (!moving.tangent(X, direction, t, det_sign)) {
    out.message = "the tangent of the path at its start could not be computed";
    out.set_converged(false);
    return out;
  }
  const double h_max = std::max(options.max_load_step, 0.02);
  double h = 0.25 * options.max_load_step;
  const double h_min = 1e-9;
  int bifurcations = 0;
  double lambda_max = X[nz];
  bool done = false;
  std::string stop;

  // Locates a sign change of `test` on the chord from states a to b by bisection; returns the
  // state on the path there.
  auto locate = [&](const VectorXd& a, const VectorXd& b, auto test, VectorXd& at) {
    const VectorXd chord = b - a;
    double lo = 0.0, hi = 1.0;
    const double test_lo = test(a, chord);
    at = b;
    bool ok = true;
    for (int it = 0; it < 50 && hi - lo > 1e-13; ++it) {
      const double mid = 0.5 * (lo + hi);
      VectorXd Xm = a + mid * chord;
      const VectorXd anchor = Xm;
      if (moving.correct(Xm, chord, anchor, 30) < 0) {
        ok = false;
        break;
      }
      ++out.location_corrections;
      const double v = test(Xm, chord);
      if ((v > 0.0) == (test_lo > 0.0)) {
        lo = mid;
      } else {
        hi = mid;
        at = Xm;
      }
    }
    return ok;
  };
  auto det_test = [&](const VectorXd& state, const VectorXd& chord) {
    int s = 0;
    double tl = 0.0;
    moving.chord_tests(state, chord, s, tl);
    return static_cast<double>(s);
  };
  auto fold_test = [&](const VectorXd& state, const VectorXd& chord) {
    int s = 0;
    double tl = 0.0;
    moving.chord_tests(state, chord, s, tl);
    return tl;
  };

  while (!done) {
    if (out.steps + out.rejected_steps >= options.max_steps) {
      stop = fmt::format("the step limit of {} was reached", options.max_steps);
      break;
    }
    if (h < h_min) {
      stop = fmt::format("the step fell below {:g} at lambda = {:.8g}", h_min, X[nz]);
      break;
    }
    VectorXd Xn = X + h * t;
    const int iterations = moving.correct(Xn, t, Xn, 10);
    bool accept = iterations >= 0;
    if (accept) {
      const double dl = std::fabs(Xn[nz] - X[nz]);
      const double dangle = (node_angles(Xn) - node_angles(X)).lpNorm<Eigen::Infinity>();
      accept = dl <= options.max_load_step * (1.0 + 1e-9) && dangle <= options.max_angle_step &&
               moving.weighted_norm(Xn - X) <= 2.0 * h;
    }
    if (!accept) {
      ++out.rejected_steps;
      h *= 0.5;
      continue;
    }
    VectorXd tn;
    int sign_n = 0;
    if (!moving.tangent(Xn, t, tn, sign_n)) {
      ++out.rejected_steps;
      h *= 0.5;
      continue;
    }
    ++out.steps;
    // Past the end of the travel: the end point itself, at lambda = 1.
    if (Xn[nz] >= 1.0 && t[nz] > 0.0) {
      VectorXd Xe = X + (1.0 - X[nz]) / (Xn[nz] - X[nz]) * (Xn - X);
      if (moving.correct_at(Xe, 1.0, 30)) {
        Xn = Xe;
        done = true;
      }
    }
    // A fold of lambda between X and Xn.
    if (!done && (tn[nz] > 0.0) != (t[nz] > 0.0)) {
      VectorXd at;
      if (locate(X, Xn, fold_test, at)) {
        ++out.limit_points;
        CbcmSpecialPoint sp;
        sp.kind = SpecialPointKind::kLimitPoint;
        sp.point = state_of(p, model, at, true, stage, branch, 2);
        sp.index = static_cast<int>(out.points.size());
        sp.index_after = sp.index + 1;
        out.points.push_back(sp.point);
        states.push_back(at);
        out.special_points.push_back(sp);
      }
    }
    // A bifurcation between X and Xn.
    if (sign_n != det_sign && sign_n != 0 && det_sign != 0) {
      VectorXd at;
      const bool located = locate(X, Xn, det_test, at);
      ++bifurcations;
      ++out.bifurcation_points;
      CbcmSpecialPoint sp;
      sp.kind = SpecialPointKind::kBifurcation;
      sp.located = located;
      sp.point = state_of(p, model, at, true, stage, branch, 4);
      sp.index = static_cast<int>(out.points.size());
      if (bifurcations == options.branch) {
        // Switch: the null direction of [dr/dz dr/dlambda] orthogonal to the path's tangent.
        VectorXd r;
        MatrixXd J;
        bool switched = false;
        if (moving.residual(at, r) && moving.jacobian(at, r, J)) {
          const Eigen::JacobiSVD<MatrixXd> svd(J, Eigen::ComputeFullV);
          const MatrixXd& V = svd.matrixV();
          const VectorXd tu = t.normalized();
          VectorXd phi = VectorXd::Zero(nz + 1);
          for (int k : {nz - 1, nz}) {
            VectorXd v = V.col(k) - V.col(k).dot(tu) * tu;
            if (v.norm() > phi.norm()) phi = v;
          }
          phi /= moving.weighted_norm(phi);
          const double side0 = side_value(at);
          for (double hs = 0.25 * options.max_load_step; hs > 1e-7 && !switched; hs *= 0.25) {
            for (double s : {1.0, -1.0}) {
              VectorXd Xs = at + s * hs * phi;
              const VectorXd anchor = Xs;
              if (moving.correct(Xs, phi, anchor, 15) < 0) continue;
              if (moving.weighted_norm(Xs - at) < 0.5 * hs) continue;
              if ((side_value(Xs) - side0 > 0.0) != (options.branch_side > 0)) continue;
              sp.switched = switched = true;
              out.switched_branch = true;
              sp.index_after = sp.index + 1;
              out.points.push_back(sp.point);
              states.push_back(at);
              out.special_points.push_back(sp);
              ++branch;
              Xn = Xs;
              VectorXd dir = (Xs - at);
              if (!moving.tangent(Xn, dir, tn, sign_n)) switched = false;
              h = hs;
              break;
            }
          }
        }
        if (!switched) {
          stop = fmt::format(
              "at the bifurcation at lambda = {:.8g} no point on the other branch was found",
              at[nz]);
          out.points.push_back(sp.point);
          out.special_points.push_back(sp);
          break;
        }
        done = false;
      } else {
        sp.index_after = sp.index + 1;
        out.points.push_back(sp.point);
        states.push_back(at);
        out.special_points.push_back(sp);
      }
    }
    if (control.one_way && !done && t[nz] > 0.0 && tn[nz] < 0.0 && X[nz] >= lambda_max - 1e-12) {
      // One way (docs/paths.md "--one-way"): the path folds back at the largest lambda reached;
      // where an equilibrium lies just beyond the turning point, the part after it is dropped and
      // the path goes on from there.
      VectorXd turn = X;
      if (!out.special_points.empty() &&
          out.special_points.back().index == static_cast<int>(out.points.size()) - 1) {
        turn = states.back();
      }
      bool went_on = false;
      for (double delta : {1e-6, 1e-5, 1e-4, 1e-3}) {
        VectorXd Xo = turn;
        if (!moving.correct_at(Xo, turn[nz] + delta, 30)) continue;
        const VectorXd angles = node_angles(Xo) - node_angles(turn);
        if (angles.lpNorm<Eigen::Infinity>() > 0.2 ||
            (Xo.head(2 * n) - turn.head(2 * n)).lpNorm<Eigen::Infinity>() > 0.2) {
          continue;
        }
        VectorXd forward = VectorXd::Zero(nz + 1);
        forward[nz] = 1.0;
        if (!moving.tangent(Xo, forward, tn, sign_n)) continue;
        if (!out.special_points.empty() &&
            out.special_points.back().index == static_cast<int>(out.points.size()) - 1) {
          out.special_points.back().switched = true;
        }
        ++branch;
        Xn = Xo;
        went_on = true;
        break;
      }
      if (!went_on) {
        stop = fmt::format(
            "--one-way: the path folds back at lambda = {:.8g} and no equilibrium lies next to it "
            "just beyond (the structure would snap there)",
            turn[nz]);
        break;
      }
    }
    X = Xn;
    t = tn;
    det_sign = sign_n;
    lambda_max = std::max(lambda_max, X[nz]);
    const CbcmPathPoint row = state_of(p, model, X, true, stage, branch, done ? 3 : 1);
    if (n == 1 && row.max_element_deflection > bcm::kValidDeflection) {
      // The BCM's stated range ends here: the crossing of |y| = 0.1 on the last step.
      out.left_domain = true;
      out.points.push_back(row);
      states.push_back(X);
      stop = fmt::format(
          "the BCM element's transverse deflection passed {:g} of its length (its stated range, "
          "Awtar et al. 2007) at lambda = {:.6g}, {} = {:.8g}; the BCM's path ends there: the "
          "chained BCM (--method cbcm --elements N) follows larger deflections",
          bcm::kValidDeflection,
          X[nz],
          to_string(control.coordinate),
          coordinate_of(row, coordinate));
      break;
    }
    out.points.push_back(row);
    states.push_back(X);
    if (!done && X[nz] < -1e-9 && t[nz] < 0.0 && X[nz] < -0.5) {
      stop = "the path turned back past its start (lambda < -0.5)";
      break;
    }
    if (iterations <= 3) h = std::min(1.5 * h, h_max);
  }
  out.lambda_reached = X[nz];
  if (done && stop.empty()) {
    out.set_converged(true);
    out.message = fmt::format(
        "{} moved from {:.9g} to {:.9g} (lambda = fraction moved) in {} "
        "steps, {} element{}",
        to_string(control.coordinate),
        start / scale,
        end / scale,
        out.steps,
        n,
        n == 1 ? "" : "s");
  } else {
    out.set_converged(false);
    out.message = stop.empty() ? "the path stopped" : stop;
  }

  // Force points on the moving stage's rows.
  const auto force_at = [&](const VectorXd& state) {
    return conjugate(state_of(p, model, state, true, stage, branch, 1), coordinate);
  };
  const auto force_point =
      [&](ForcePointKind kind, const VectorXd& state, int before, bool located, int row_branch) {
        CbcmForcePoint f;
        f.kind = kind;
        f.point = state_of(p, model, state, true, stage, row_branch, 1);
        f.coordinate = coordinate_of(f.point, coordinate);
        f.force = conjugate(f.point, coordinate);
        f.index_before = before;
        f.located = located;
        if (f.kind == ForcePointKind::kZero) {
          VectorXd tz;
          int s = 0;
          VectorXd dir = VectorXd::Zero(nz + 1);
          dir[nz] = 1.0;
          f.slope = std::numeric_limits<double>::quiet_NaN();
          if (moving.tangent(state, dir, tz, s)) {
            const double eps = 1e-6;
            const CbcmPathPoint a =
                state_of(p, model, state - eps * tz, true, stage, row_branch, 1);
            const CbcmPathPoint b =
                state_of(p, model, state + eps * tz, true, stage, row_branch, 1);
            const double dc = coordinate_of(b, coordinate) - coordinate_of(a, coordinate);
            if (dc != 0.0) f.slope = (conjugate(b, coordinate) - conjugate(a, coordinate)) / dc;
          }
        }
        out.force_points.push_back(f);
      };
  const std::size_t count = states.size();
  const std::size_t offset = static_cast<std::size_t>(first_row);
  std::vector<double> F(count);
  double force_scale = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    F[i] = conjugate(out.points[offset + i], coordinate);
    force_scale = std::max(force_scale, std::fabs(F[i]));
  }
  for (std::size_t i = 1; i < count; ++i) {
    const int row_branch = out.points[offset + i].branch;
    // (The unloaded start, where the force is 0 to rounding, is no zero crossing.)
    const bool at_rest = i == 1 && std::fabs(F[0]) <= 1e-9 * force_scale;
    if (!at_rest && (F[i - 1] == 0.0 || (F[i - 1] > 0.0) != (F[i] > 0.0))) {
      if (F[i - 1] == 0.0 && i > 1) continue;
      VectorXd at;
      const bool ok = locate(
          states[i - 1],
          states[i],
          [&](const VectorXd& s, const VectorXd&) { return force_at(s); },
          at);
      force_point(ForcePointKind::kZero, at, static_cast<int>(offset + i - 1), ok, row_branch);
    }
    if (i + 1 < count) {
      const bool maximum = F[i] > F[i - 1] && F[i] > F[i + 1];
      const bool minimum = F[i] < F[i - 1] && F[i] < F[i + 1];
      if (!maximum && !minimum) continue;
      const int status = out.points[offset + i].status;
      if (status == 4) {  // a corner where the path switched: the point itself
        force_point(maximum ? ForcePointKind::kMaximum : ForcePointKind::kMinimum,
                    states[i],
                    static_cast<int>(offset + i - 1),
                    true,
                    row_branch);
        continue;
      }
      // Golden section on each chord around the sample; the better of the two.
      const double sign = maximum ? 1.0 : -1.0;
      std::optional<VectorXd> best;
      double best_value = sign * F[i];
      for (std::size_t a : {i - 1, i}) {
        const VectorXd chord = states[a + 1] - states[a];
        auto on_chord = [&](double tau, VectorXd& Xc) {
          Xc = states[a] + tau * chord;
          const VectorXd anchor = Xc;
          ++out.location_corrections;
          return moving.correct(Xc, chord, anchor, 30) >= 0;
        };
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        double lo = 0.0, hi = 1.0;
        double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
        VectorXd X1, X2;
        if (!on_chord(x1, X1) || !on_chord(x2, X2)) continue;
        double f1 = sign * force_at(X1), f2 = sign * force_at(X2);
        for (int it = 0; it < 60 && hi - lo > 1e-10; ++it) {
          if (f1 > f2) {
            hi = x2;
            x2 = x1;
            X2 = X1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            if (!on_chord(x1, X1)) break;
            f1 = sign * force_at(X1);
          } else {
            lo = x1;
            x1 = x2;
            X1 = X2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            if (!on_chord(x2, X2)) break;
            f2 = sign * force_at(X2);
          }
        }
        const double value = std::max(f1, f2);
        if (value >= best_value) {
          best_value = value;
          best = f1 > f2 ? X1 : X2;
        }
      }
      force_point(maximum ? ForcePointKind::kMaximum : ForcePointKind::kMinimum,
                  best ? *best : states[i],
                  static_cast<int>(offset + i - 1),
                  best.has_value(),
                  row_branch);
    }
  }
  out.newton_iterations += moving.newton_iterations;
  return out;
}

}  // namespace flexure
