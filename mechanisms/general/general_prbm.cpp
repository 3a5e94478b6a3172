#include <algorithm>
#include <cmath>
#include <sstream>

#include "flexure/mechanisms/general/arclength_path.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/prbm_assembly.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Singular values below this fraction of the largest (or of 1) count as zero when the rank of the
// constraint Jacobian and the admissible directions are taken.
constexpr double kRankTolerance = 1e-9;

std::string fmt(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

// Orthonormal basis of the null space of A (rows: constraints), from its SVD.
MatrixXd null_space(const MatrixXd& A, int cols) {
  if (A.rows() == 0) {
    return MatrixXd::Identity(cols, cols);
  }
  Eigen::JacobiSVD<MatrixXd> svd(A, Eigen::ComputeFullV);
  const VectorXd& sv = svd.singularValues();
  const double cut = kRankTolerance * std::max(1.0, sv.size() > 0 ? sv[0] : 0.0);
  int rank = 0;
  for (int i = 0; i < sv.size(); ++i) {
    rank += sv[i] > cut ? 1 : 0;
  }
  return svd.matrixV().rightCols(cols - rank);
}

int rank_of(const MatrixXd& A) {
  if (A.rows() == 0) {
    return 0;
  }
  Eigen::JacobiSVD<MatrixXd> svd(A);
  const VectorXd& sv = svd.singularValues();
  const double cut = kRankTolerance * std::max(1.0, sv[0]);
  int rank = 0;
  for (int i = 0; i < sv.size(); ++i) {
    rank += sv[i] > cut ? 1 : 0;
  }
  return rank;
}

// The verdict of the reduced second variation Z^T H Z against the springs' unloaded stiffness
// Z^T B Z (generalized eigenvalues: the margin is 1 for the unloaded springs, 0 at a critical
// state; docs/stability.md "Mechanisms").
Stability verdict(const MatrixXd& H,
                  const MatrixXd& B,
                  const MatrixXd& Z,
                  double tolerance,
                  const std::string& control) {
  if (Z.cols() == 0) {
    Stability s = classify_stability(0, 1.0, tolerance, "the mechanism");
    s.message = "stable by convention under " + control +
                " control: the PRB linkage has no free direction (margin 1, the unloaded value)";
    return s;
  }
  const MatrixXd Hr = Z.transpose() * H * Z;
  const MatrixXd Br = Z.transpose() * B * Z;
  // The stiffest spring, in the same coordinates: what "no stiffness" is measured against.
  const double reference = std::max(
      Eigen::SelfAdjointEigenSolver<MatrixXd>(B, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff(),
      0.0);
  Eigen::SelfAdjointEigenSolver<MatrixXd> b_eig(Br, Eigen::EigenvaluesOnly);
  const double b_min = b_eig.eigenvalues().minCoeff();
  VectorXd eig;
  std::string note;
  if (reference > 0.0 && b_min > kRankTolerance * reference) {
    Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> g(Hr, Br, Eigen::EigenvaluesOnly);
    eig = g.eigenvalues();
  } else {
    // A free direction that strains no spring to first order (a toggle position, a linkage
    // without springs): the margin is measured against the stiffest spring instead.
    Eigen::SelfAdjointEigenSolver<MatrixXd> h(Hr, Eigen::EigenvaluesOnly);
    eig = h.eigenvalues() / (reference > 0.0 ? reference : 1.0);
    note =
        " (a free direction strains no spring to first order: margin relative to the stiffest "
        "spring)";
  }
  int index = 0;
  for (int i = 0; i < eig.size(); ++i) {
    index += eig[i] < -tolerance ? 1 : 0;
  }
  Stability s = classify_stability(index, eig.minCoeff(), tolerance, "the mechanism");
  s.message += " under " + control + " control" + note;
  return s;
}

class PathSolver {
 public:
  PathSolver(const PrbmAssembly& assembly, const GeneralPrbmOptions& options)
      : a_(assembly),
        o_(options),
        N_(assembly.coordinate_count()),
        m_(assembly.constraint_count()),
        n_(N_ + m_ + 2) {}

  int lambda_index() const { return N_ + m_; }
  int s_index() const { return N_ + m_ + 1; }
  int size() const { return n_; }

  VectorXd q(const VectorXd& z) const { return z.head(N_); }
  VectorXd mu(const VectorXd& z) const { return z.segment(N_, m_); }

  VectorXd F(const VectorXd& z) const {
    VectorXd f(n_ - 1);
    const VectorXd qq = q(z);
    f.head(N_) = a_.lagrangian_gradient(qq, mu(z), z[lambda_index()]);
    f.segment(N_, m_) = a_.constraints(qq);
    f[N_ + m_] = a_.input(qq) - z[s_index()];
    return f;
  }

  MatrixXd JF(const VectorXd& z) const {
    const VectorXd qq = q(z);
    MatrixXd J = MatrixXd::Zero(n_ - 1, n_);
    const MatrixXd Jg = a_.constraint_jacobian(qq);
    const VectorXd gc = a_.input_gradient(qq);
    J.topLeftCorner(N_, N_) = a_.lagrangian_hessian(qq, mu(z), z[lambda_index()]);
    J.block(0, N_, N_, m_) = -Jg.transpose();
    J.col(lambda_index()).head(N_) = -gc;
    J.block(N_, 0, m_, N_) = Jg;
    J.block(N_ + m_, 0, 1, N_) = gc.transpose();
    J(N_ + m_, s_index()) = -1.0;
    return J;
  }

 private:
  const PrbmAssembly& a_;
  const GeneralPrbmOptions& o_;
  int N_, m_, n_;
};

}  // namespace

void GeneralPrbmOptions::validate() const {
  if (!(tolerance > 0.0) || !(tolerance < 1e-3)) {
    throw InvalidInput("GeneralPrbmOptions.tolerance must be in (0, 1e-3)");
  }
  if (max_newton_iterations < 1 || max_steps < 1) {
    throw InvalidInput("GeneralPrbmOptions.max_newton_iterations and max_steps must be >= 1");
  }
  if (!(max_step > 0.0) || !(max_step <= 1.0)) {
    throw InvalidInput("GeneralPrbmOptions.max_step must be in (0, 1]");
  }
  if (!(critical_tolerance >= 0.0) || !std::isfinite(critical_tolerance)) {
    throw InvalidInput("GeneralPrbmOptions.critical_tolerance must be finite and >= 0");
  }
}

int check_general_mechanism(const GeneralMechanism& mechanism) {
  const PrbmAssembly A(mechanism);
  const int N = A.coordinate_count();
  const int m = A.constraint_count();
  const std::vector<std::string> all_names = A.body_names();
  const VectorXd q0 = VectorXd::Zero(N);
  const MatrixXd Jg0 = A.constraint_jacobian(q0);
  const int rank_g = rank_of(Jg0);
  if (rank_g < m) {
    throw InvalidInput(mechanism.where(0) +
                       "the joints are redundant in the described "
                       "configuration (" +
                       std::to_string(m) + " constraint equations of rank " +
                       std::to_string(rank_g) +
                       "): the PRBM assembler needs independent joints (over-constrained "
                       "mechanisms are not supported)");
  }
  const int dof = N - rank_g;
  MatrixXd Jdc0(m + 1, N);
  Jdc0 << Jg0, A.input_gradient(q0).transpose();
  const bool start_given = !mechanism.input.start_rotation.empty();
  if (dof == 0) {
    throw InvalidInput(mechanism.where(mechanism.input.line) +
                       "input: the joints leave the mechanism no freedom to move (0 degrees of "
                       "freedom)");
  }
  if (rank_of(Jdc0) == rank_g && !start_given) {
    throw InvalidInput(mechanism.where(mechanism.input.line) +
                       "input: the input coordinate cannot move to first order in the described "
                       "configuration (a dead point, e.g. a straight slider-crank); give the "
                       "input a start_rotation of the bodies that says which way the mechanism "
                       "leaves it");
  }
  {
    const MatrixXd Z = null_space(Jdc0, N);
    if (Z.cols() > 0) {
      const MatrixXd Br = Z.transpose() * A.unloaded_stiffness(q0) * Z;
      Eigen::SelfAdjointEigenSolver<MatrixXd> e(Br);
      const double scale = std::max(1.0, e.eigenvalues().maxCoeff());
      if (e.eigenvalues().minCoeff() < 1e-10 * scale) {
        const VectorXd v = Z * e.eigenvectors().col(0);
        int worst = 0;
        double largest = -1.0;
        for (int b = 0; b < N / 3; ++b) {
          const double motion = v.segment(3 * b, 3).norm();
          if (motion > largest) {
            largest = motion;
            worst = b;
          }
        }
        throw InvalidInput(mechanism.where(0) + "body '" + all_names[worst] +
                           "' can move with the input held without straining any spring: it "
                           "is unconstrained (add a joint, a flexure or a spring)");
      }
    }
  }

  return dof;
}

std::string input_value_text(const Input& input, double value) {
  if (input.coordinate != InputCoordinate::kAngle) return fmt(value) + " m";
  return fmt(value) + " rad (" + fmt(value * 180.0 / std::acos(-1.0)) + " deg)";
}

GeneralPrbmResult solve_general_prbm(const GeneralMechanism& mechanism,
                                     const GeneralPrbmOptions& options) {
  options.validate();
  for (const Flexure& f : mechanism.flexures) {
    if (f.model != FlexureModel::kPrbm) {
      throw InvalidInput(mechanism.where(f.line) + "flexure '" + f.name + "': model '" +
                         std::string(flexure_model_name(f.model)) +
                         "' asks for a model per flexure: --model mixed "
                         "(solve_general_mixed) gives each flexure its own; the PRBM solves every "
                         "flexure as a PRBM element (solve_general_exact every one exactly)");
    }
  }
  mechanism.validate();
  for (const Flexure& f : mechanism.flexures) {
    // What Howell's elements do not cover (docs/mechanisms.md "Curved and tapered flexures").
    const std::string item = mechanism.where(f.line) + "flexure '" + f.name + "'";
    if (f.tapered()) {
      throw InvalidInput(item +
                         ": tapered (width_tip, thickness_tip): the PRBM has no tapered element "
                         "(Howell ch. 5's are uniform); solve it with --model exact");
    }
    if (f.curved()) {
      const Vec2 a = mechanism.point(f.a), b = mechanism.point(f.b);
      const double kappa0 = f.curvature * f.arc_length(std::hypot(b.x - a.x, b.y - a.y));
      if (f.prbm != PrbmKind::kFixedPinned) {
        throw InvalidInput(item + ": initially curved (curvature " + fmt(f.curvature) +
                           " 1/m), but prbm = \"" + std::string(prbm_kind_name(f.prbm)) +
                           "\": the PRBM covers a curved flexure only as Howell's initially "
                           "curved cantilever (§5.5), prbm = \"fixed-pinned\"; or solve it with "
                           "--model exact");
      }
      if (std::fabs(kappa0) > 2.0) {
        throw InvalidInput(item + ": kappa0 = curvature x length = " + fmt(kappa0) +
                           " is outside Howell's Table 5.2 (|kappa0| <= 2), the initially curved "
                           "cantilever's constants; solve it with --model exact");
      }
    }
  }
  const PrbmAssembly A(mechanism);
  PathSolver P(A, options);
  ArclengthCurve curve;
  curve.size = P.size();
  curve.residual = [&](const VectorXd& z, VectorXd& f) {
    f = P.F(z);
    return true;
  };
  curve.jacobian = [&](const VectorXd& z, MatrixXd& J) {
    J = P.JF(z);
    return true;
  };
  curve.weight = VectorXd::Ones(P.size());
  ArclengthPath path(
      std::move(curve),
      {options.tolerance, options.max_newton_iterations, options.max_step, options.max_steps});
  const int N = A.coordinate_count();
  const int m = A.constraint_count();
  const int li = P.lambda_index();
  const int si = P.s_index();

  GeneralPrbmResult result;
  for (const Flexure& f : mechanism.flexures) {
    const Vec2 a = mechanism.point(f.a);
    const Vec2 b = mechanism.point(f.b);
    const double ratio = f.thickness / f.arc_length(std::hypot(b.x - a.x, b.y - a.y));
    if (ratio > 0.5) {
      result.warn(WarningKind::kOutsideValidity,
                  "flexure '" + f.name + "': thickness/length = " + fmt(ratio) +
                      " > 0.5, outside slender-beam theory; its PRBM spring is the textbook "
                      "value, not a beam result (docs/mechanisms.md, geometry limits)");
    }
  }
  const std::vector<std::string> all_names = A.body_names();
  result.body_names.assign(all_names.begin(), all_names.begin() + A.described_body_count());

  // The PRB elements' links keep their length: an extensible flexure has no PRBM. Where the
  // mechanism needs the stretch to move at all (an inclined beam between a clamp and a guided
  // shuttle: 0 degrees of freedom with rigid links) say so instead of the count of freedoms;
  // elsewhere the PRBM answers without the axial strain, and says that too.
  std::vector<std::string> extensible;
  for (const Flexure& f : mechanism.flexures) {
    if (f.extensible) extensible.push_back(f.name);
  }
  try {
    result.degrees_of_freedom = check_general_mechanism(mechanism);
  } catch (const InvalidInput& e) {
    if (extensible.empty()) throw;
    throw InvalidInput(std::string(e.what()) + " -- flexure '" + extensible.front() +
                       "' is extensible (extensible = true): it moves by stretching, which the "
                       "PRBM's rigid links cannot (their length is fixed); solve it with --model "
                       "exact");
  }
  for (const std::string& name : extensible) {
    result.warn(WarningKind::kOutsideValidity,
                "flexure '" + name +
                    "': extensible = true is for the exact model; the PRBM element keeps its "
                    "length (no axial strain)");
  }
  const bool start_given = !mechanism.input.start_rotation.empty();
  const VectorXd q0 = VectorXd::Zero(N);

  // The described configuration, projected onto the constraints (s held at its value there).
  VectorXd z = VectorXd::Zero(P.size());
  z[si] = A.input(q0);
  if (!path.newton_fixed(z, si)) {
    result.termination = Termination::kNoConvergence;
    result.message = "Newton did not converge at the described configuration";
    return result;
  }

  const bool displacement = mechanism.input.control == InputControl::kDisplacement;
  const int p = displacement ? si : li;
  const Input& in = mechanism.input;
  auto scaled_param = [&](double v) { return displacement ? A.input_scaled(v) : A.load_scaled(v); };
  std::vector<double> grid(static_cast<std::size_t>(in.count));
  for (int i = 0; i < in.count; ++i) {
    grid[static_cast<std::size_t>(i)] =
        scaled_param(in.start + (in.stop - in.start) * i / (in.count - 1));
  }

  std::size_t reported = 0;  // options.progress: points reported, never decreasing
  auto record = [&](const VectorXd& zz) {
    const VectorXd qq = P.q(zz);
    const VectorXd mu = P.mu(zz);
    const double lambda = zz[li];
    GeneralPrbmPoint pt;
    pt.input = A.input_si(zz[si]);
    pt.input_load = A.load_si(lambda);
    pt.energy = A.energy_si(A.energy(qq));
    pt.spring_energy = A.energy_si(A.spring_energy(qq));
    const MatrixXd H = A.lagrangian_hessian(qq, mu, lambda);
    const MatrixXd B = A.unloaded_stiffness(qq);
    const MatrixXd Jg = A.constraint_jacobian(qq);
    MatrixXd Jdc(m + 1, N);
    Jdc << Jg, A.input_gradient(qq).transpose();
    pt.force_control = verdict(H, B, null_space(Jg, N), options.critical_tolerance, "force");
    pt.displacement_control =
        verdict(H, B, null_space(Jdc, N), options.critical_tolerance, "displacement");
    for (int b = 0; b < A.described_body_count(); ++b) {
      pt.body_x.push_back(qq[3 * b] * A.length_scale());
      pt.body_y.push_back(qq[3 * b + 1] * A.length_scale());
      pt.body_phi.push_back(qq[3 * b + 2]);
    }
    fill_point_results(mechanism, A, qq, mu, /*assembled_flexures=*/true, pt);
    result.points.push_back(std::move(pt));
    if (options.progress) {
      // A value crossed again after a limit point records a point more than the grid has.
      reported = std::min(std::max(reported, result.points.size()), grid.size());
      options.progress(reported, grid.size());
    }
  };

  ArclengthPath::Follow how;
  how.controlled = p;
  how.limit = [&](const VectorXd& zl) {
    result.limit_inputs.push_back(A.input_si(zl[si]));
    result.limit_loads.push_back(A.load_si(zl[li]));
  };
  ArclengthPath::Follow recording = how;
  recording.grid = &grid;
  recording.record = record;

  Termination end = Termination::kConverged;
  if (start_given) {
    // Newton for the first grid value directly, from the given body rotations.
    z.setZero();
    const std::vector<std::string> names = A.body_names();
    for (const auto& [body, angle] : in.start_rotation) {
      const auto it = std::find(names.begin(), names.end(), body);
      z[3 * (it - names.begin()) + 2] = angle;
    }
    z[si] = A.input(P.q(z));
    z[p] = grid.front();
    if (!path.newton_fixed(z, p)) {
      result.termination = Termination::kNoConvergence;
      result.message =
          "Newton did not converge at the first input value from the given "
          "start_rotation";
      return result;
    }
  } else if (z[p] != grid.front()) {
    end = path.follow(z, grid.front(), how);
  }
  if (end == Termination::kConverged) {
    record(z);
    result.limit_inputs.clear();
    result.limit_loads.clear();
    end = path.follow(z, grid.back(), recording);
  }
  const int steps = path.steps();
  result.iterations = steps;
  result.termination = end;
  if (end == Termination::kLimitPoint) {
    result.message =
        "the path did not reach the end of the input range after " + std::to_string(steps) +
        " steps" +
        (result.limit_inputs.empty()
             // No fold: the input creeps towards a dead point of the linkage while the load that
             // holds it grows without bound (a rigid PRB linkage at the end of its travel).
             ? "; it came no further than input " + input_value_text(in, A.input_si(z[si])) +
                   ", held by an input load of " + fmt(A.load_si(z[li])) +
                   (in.coordinate == InputCoordinate::kAngle ? " N m" : " N") +
                   (displacement ? " (the end of the linkage's travel: end the input range before "
                                   "it)"
                                 : "")
             : "; it turned back at a limit point at input " +
                   input_value_text(in, result.limit_inputs.front()));
  } else if (end == Termination::kNoConvergence) {
    result.message = "the continuation failed after " + std::to_string(steps) + " steps (" +
                     std::to_string(result.points.size()) + " of " + std::to_string(in.count) +
                     " points)";
  }

  // Equilibria of the unloaded mechanism: sign changes of the input load along the path.
  std::vector<VectorXd> failed;
  for (const VectorXd& ze : path.zeros_along(li, &failed)) {
    const double s = A.input_si(ze[si]);
    if (!result.equilibria.empty() &&
        std::fabs(result.equilibria.back().input - s) <
            1e-9 * std::max(1.0, std::fabs(s)) * (A.input_is_angle() ? 1.0 : A.length_scale())) {
      continue;
    }
    const VectorXd qq = P.q(ze);
    GeneralEquilibrium e;
    e.input = s;
    e.energy = A.energy_si(A.energy(qq));
    e.stability = verdict(A.lagrangian_hessian(qq, P.mu(ze), 0.0),
                          A.unloaded_stiffness(qq),
                          null_space(A.constraint_jacobian(qq), N),
                          options.critical_tolerance,
                          "force");
    result.equilibria.push_back(std::move(e));
  }
  for (const VectorXd& zf : failed) {
    result.warn(WarningKind::kOther,
                "an equilibrium near input " + fmt(A.input_si(zf[si])) +
                    " was bracketed but Newton did not converge");
  }
  result.residual = path.worst_residual();
  return result;
}

}  // namespace flexure::mechanism::general
