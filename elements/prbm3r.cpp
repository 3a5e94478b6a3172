#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>

#include "flexure/elements/data_files.h"
#include "flexure/elements/ladder_models.h"
#include "flexure/elements/load_path_newton.h"
#include "flexure/solver/common/csv_table.h"
#include "flexure/solver/common/enum_names.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

Prbm3rConstants read_set(const EmbeddedFile& file, std::string_view name, std::string source) {
  const CsvTable t = CsvTable::parse(file);
  for (std::size_t i = 0; i < t.row_count(); ++i) {
    if (t.text(i, "name") != name) continue;
    Prbm3rConstants c;
    for (int j = 0; j < 4; ++j) c.gamma[j] = t.number(i, fmt::format("gamma{}", j));
    for (int j = 0; j < 3; ++j) c.k[j] = t.number(i, fmt::format("k{}", j + 1));
    c.name = std::string(name);
    c.source = std::move(source);
    c.validate();
    return c;
  }
  throw InvalidInput(fmt::format("{}: no row named '{}'", t.source(), name));
}

}  // namespace

Prbm3rConstants Prbm3rConstants::su() {
  static const Prbm3rConstants c =
      read_set(data::su_prbm3r_constants(), "su", "Su 2009, the general set");
  return c;
}

Prbm3rConstants Prbm3rConstants::su_moment() {
  static const Prbm3rConstants c = read_set(
      data::su_prbm3r_constants(), "su-moment", "Su 2009, the set fitted to an end moment");
  return c;
}

Prbm3rConstants Prbm3rConstants::su_force() {
  static const Prbm3rConstants c = read_set(
      data::su_prbm3r_constants(), "su-force", "Su 2009, the set fitted to a transverse force");
  return c;
}

Prbm3rConstants Prbm3rConstants::flexure() {
  static const Prbm3rConstants c =
      read_set(data::prbm3r_flexure_constants(),
               "flexure",
               "derived by flexure against the exact elastica (data/prbm3r_flexure_constants.csv)");
  return c;
}

namespace {
constexpr std::array<const char*, 4> kSetNames = {"su", "su-moment", "su-force", "flexure"};
}  // namespace

const char* to_string(Prbm3rConstantSet set) { return enum_name(kSetNames, set); }

Prbm3rConstantSet prbm3r_constant_set_from_string(std::string_view name) {
  // Case-insensitive, and a refusal in the words `--constants` always used (not enum_from_name's).
  if (const auto set = enum_find<Prbm3rConstantSet>(kSetNames, to_lower(name))) return *set;
  throw InvalidInput(fmt::format(
      "PR-3R constants '{}' are unknown (allowed: {})", name, fmt::join(kSetNames, ", ")));
}

Prbm3rConstants Prbm3rConstants::of(Prbm3rConstantSet set) {
  switch (set) {
    case Prbm3rConstantSet::kSu:
      return su();
    case Prbm3rConstantSet::kSuMoment:
      return su_moment();
    case Prbm3rConstantSet::kSuForce:
      return su_force();
    case Prbm3rConstantSet::kFlexure:
      return flexure();
  }
  throw InvalidInput(fmt::format("Prbm3rConstantSet {} is not a stored set of PR-3R constants",
                                 static_cast<int>(set)));
}

const std::vector<std::string>& Prbm3rConstants::names() {
  static const std::vector<std::string> n(kSetNames.begin(), kSetNames.end());
  return n;
}

Prbm3rConstants Prbm3rConstants::by_name(std::string_view name) {
  return of(prbm3r_constant_set_from_string(name));
}

double Prbm3rConstants::joint_arc_length(int i) const {
  double s = 0.0;
  for (int j = 0; j < i; ++j) s += gamma[static_cast<std::size_t>(j)];
  return s;
}

double Prbm3rConstants::small_load_b_per_force() const {
  double sum = 0.0;
  for (int i = 1; i <= 3; ++i) {
    const double arm = 1.0 - joint_arc_length(i);
    sum += arm * arm / k[static_cast<std::size_t>(i - 1)];
  }
  return sum;
}

double Prbm3rConstants::small_load_theta_per_force() const {
  double sum = 0.0;
  for (int i = 1; i <= 3; ++i) sum += (1.0 - joint_arc_length(i)) / k[i - 1];
  return sum;
}

double Prbm3rConstants::small_load_theta_per_moment() const {
  return 1.0 / k[0] + 1.0 / k[1] + 1.0 / k[2];
}

void Prbm3rConstants::validate() const {
  double sum = 0.0;
  for (int j = 0; j < 4; ++j) {
    const std::string what = fmt::format("PR-3R link length gamma{}", j);
    require_finite(gamma[j], what);
    if (!(gamma[j] > 0.0))
      throw InvalidInput(fmt::format("{} must be > 0 (got {})", what, gamma[j]));
    sum += gamma[j];
  }
  if (std::fabs(sum - 1.0) > 1e-6) {
    throw InvalidInput(
        fmt::format("the PR-3R link lengths gamma0..gamma3 must sum to 1 (got {:.9g})", sum));
  }
  for (int j = 0; j < 3; ++j) {
    const std::string what = fmt::format("PR-3R spring stiffness k{}", j + 1);
    require_finite(k[j], what);
    if (!(k[j] > 0.0)) throw InvalidInput(fmt::format("{} must be > 0 (got {})", what, k[j]));
  }
}

void Prbm3rSolver::Options::validate() const {
  constants.validate();
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    throw InvalidInput(fmt::format("PR-3R tolerance must be finite and > 0 (got {})", tolerance));
  }
  if (max_iterations < 1) {
    throw InvalidInput(fmt::format("PR-3R max_iterations must be >= 1 (got {})", max_iterations));
  }
  if (max_load_steps < 1) {
    throw InvalidInput(fmt::format("PR-3R max_load_steps must be >= 1 (got {})", max_load_steps));
  }
}

Prbm3rSolver::Prbm3rSolver() : Prbm3rSolver(Options{}) {}

Prbm3rSolver::Prbm3rSolver(Options options) : options_(std::move(options)) { options_.validate(); }

std::array<ChainPose, 5> Prbm3rSolver::joints(const std::array<double, 3>& angles) const {
  const Prbm3rConstants& c = options_.constants;
  std::array<ChainPose, 5> p{};
  p[1] = {c.gamma[0], 0.0, 0.0};
  for (int j = 1; j <= 3; ++j) {
    const double link = p[j].theta + angles[j - 1];
    p[j].theta = link;  // the joint's outgoing link angle
    p[j + 1] = {p[j].x + c.gamma[j] * std::cos(link), p[j].y + c.gamma[j] * std::sin(link), link};
  }
  return p;
}

Prbm3rResult Prbm3rSolver::solve(const CantileverCase& problem) const {
  problem.validate("prbm3r");
  const Prbm3rConstants& c = options_.constants;
  const bool guided = problem.end == EndCondition::kGuided;
  const EndLoad& load = problem.load;
  const int size = guided ? 4 : 3;
  const auto angles_of = [](const Eigen::VectorXd& z) {
    return std::array<double, 3>{z[0], z[1], z[2]};
  };
  // The unknowns: the joint angles, and on a guided end the guide's moment.
  const auto residual = [&](const Eigen::VectorXd& z, double lambda, Eigen::VectorXd& r) {
    const std::array<ChainPose, 5> p = joints(angles_of(z));
    const double Fx = lambda * load.Fx, Fy = lambda * load.Fy;
    const double M = guided ? z[3] : lambda * load.mu;
    r.resize(size);
    for (int i = 1; i <= 3; ++i) {
      const double arm = (p[4].x - p[i].x) * Fy - (p[4].y - p[i].y) * Fx + M;
      r[i - 1] = c.k[i - 1] * z[i - 1] - arm;
    }
    if (guided) r[3] = z[0] + z[1] + z[2] - lambda * problem.guided_tip_angle;
    return true;
  };
  // d r_i / d theta_j = k_i delta_ij + (y_tip - y_m) Fy + (x_tip - x_m) Fx, m = max(i, j): the
  // Hessian of V (elements/ladder_models.h).
  const auto jacobian = [&](const Eigen::VectorXd& z, double lambda, Eigen::MatrixXd& J) {
    const std::array<ChainPose, 5> p = joints(angles_of(z));
    const double Fx = lambda * load.Fx, Fy = lambda * load.Fy;
    J.setZero(size, size);
    for (int i = 1; i <= 3; ++i) {
      for (int j = 1; j <= 3; ++j) {
        const int m = std::max(i, j);
        J(i - 1, j - 1) =
            (i == j ? c.k[i - 1] : 0.0) + (p[4].y - p[m].y) * Fy + (p[4].x - p[m].x) * Fx;
      }
      if (guided) {
        J(i - 1, 3) = -1.0;
        J(3, i - 1) = 1.0;
      }
    }
    return true;
  };
  // The three link angles beyond the joints (load_path_newton.h watches every one).
  const auto link_angles = [](const Eigen::VectorXd& z) {
    return Eigen::Vector3d(z[0], z[0] + z[1], z[0] + z[1] + z[2]).eval();
  };
  const detail::MeasureFunction measure = [&](const Eigen::VectorXd& z) -> Eigen::VectorXd {
    return link_angles(z);
  };
  detail::LoadPathOptions path;
  path.tolerance = options_.tolerance *
                   std::max({1.0, std::fabs(load.Fx), std::fabs(load.Fy), std::fabs(load.mu)});
  path.max_iterations = options_.max_iterations;
  path.max_load_steps = options_.max_load_steps;
  Eigen::VectorXd z = Eigen::VectorXd::Zero(size);
  const detail::LoadPathOutcome outcome =
      detail::follow_load_path(z, residual, jacobian, measure, path);

  Prbm3rResult out;
  out.iterations = outcome.iterations;
  out.residual = outcome.residual;
  out.load_steps = outcome.load_steps;
  out.load_factor = outcome.load_factor;
  out.set_converged(outcome.converged);
  out.message = outcome.converged ? fmt::format("proportional loading in {} step{} ({} constants)",
                                                outcome.load_steps,
                                                outcome.load_steps == 1 ? "" : "s",
                                                c.name)
                                  : outcome.message;
  out.joint_angles = angles_of(z);
  const std::array<ChainPose, 5> p = joints(out.joint_angles);
  out.tip = {p[4].x, p[4].y, p[4].theta};
  const double lf = outcome.load_factor;
  const EndLoad reached = load.scaled(lf);
  out.end_moment = guided ? z[3] : reached.mu;
  out.root_moment = root_moment_of(out.tip, reached, out.end_moment);
  // Stability: the Hessian of V (the Jacobian's angle block), on a guided end restricted to
  // rotations that keep theta0 (a basis of the plane sum dtheta = 0).
  Eigen::MatrixXd J;
  jacobian(z, lf, J);
  Eigen::Matrix3d H = J.topLeftCorner(3, 3);
  if (guided) {
    Eigen::Matrix<double, 3, 2> basis;
    basis << 1, 0, -1, 1, 0, -1;
    const Eigen::Matrix2d reduced = basis.transpose() * H * basis;
    out.stable = Eigen::LLT<Eigen::Matrix2d>(reduced).info() == Eigen::Success;
  } else {
    out.stable = Eigen::LLT<Eigen::Matrix3d>(H).info() == Eigen::Success;
  }
  return out;
}

std::vector<ShapePoint> Prbm3rSolver::shape(const Prbm3rResult& result, int count) const {
  if (count < 2) throw InvalidInput("the PR-3R model's shape needs at least 2 points");
  const std::array<ChainPose, 5> p = joints(result.joint_angles);
  const Prbm3rConstants& c = options_.constants;
  std::vector<ShapePoint> out;
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double s = static_cast<double>(i) / (count - 1);
    int link = 0;
    while (link < 3 && s > c.joint_arc_length(link + 1)) ++link;
    const double along = s - c.joint_arc_length(link);
    const double angle = p[link].theta;
    out.push_back(
        {s, p[link].x + along * std::cos(angle), p[link].y + along * std::sin(angle), angle});
  }
  return out;
}

}  // namespace flexure
