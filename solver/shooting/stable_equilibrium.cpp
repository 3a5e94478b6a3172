#include "flexure/solver/shooting/stable_equilibrium.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <variant>

#include "flexure/solver/chain_model/second_variation.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

// The angle of a node of the discrete model: a free variable q[var] (or none, var < 0) plus a
// constant (rigid kinks before it; the prescribed tip angle for the fixed last node).
struct Point {
  int var = -1;
  double offset = 0.0;
  double s = 0.0;  // arc length
};

// Where a node angle enters the positions: a flexible element's end (weight h/2, trapezoid rule)
// or a rigid link (weight its length, direction the node angle plus `offset`).
struct Occurrence {
  int point = 0;
  double offset = 0.0;
  double weight = 0.0;
  int segment = 0;
};

struct Element {
  int a = 0, b = 0;  // points
  double h = 0.0;
  double k = 0.0;        // int_e EI ds / h^2
  double kappa_h = 0.0;  // stress-free turn kappa0 h
};

// A node angle as (point, extra offset): where node moments act.
struct NodeAngle {
  int point = 0;
  double offset = 0.0;
};

// The discrete chain of stable_equilibrium.h, step 1.
class DiscreteChain {
 public:
  DiscreteChain(const SegmentChain& chain, const std::vector<int>& elements)
      : chain_(chain), mask_(prescribed_mask(chain.end)), target_(chain.prescribed_tip()) {
    const int n_segments = chain.segment_count();
    // Dead force distal to each segment (the tip force and the node forces beyond it).
    segment_force_.assign(n_segments, Eigen::Vector2d(chain.tip_load.Fx, chain.tip_load.Fy));
    for (const NodeLoad& load : chain.node_loads) {
      for (int j = 0; j < load.node; ++j) segment_force_[j] += Eigen::Vector2d(load.Fx, load.Fy);
    }
    points_.push_back(Point{-1, 0.0, 0.0});
    int current = 0;     // point whose angle the chain carries on
    double extra = 0.0;  // rigid kinks since that point
    double s = 0.0;
    std::size_t flexible_index = 0;
    int last_flexible_point = -1;
    node_angles_.resize(n_segments + 1);
    for (int j = 0; j < n_segments; ++j) {
      if (const auto* f = std::get_if<FlexibleSegment>(&chain.segments[j])) {
        const int count = elements.at(flexible_index++);
        const double h = f->length / count;
        points_.push_back(Point{points_[current].var, points_[current].offset + extra, s});
        int a = static_cast<int>(points_.size()) - 1;
        for (int i = 1; i <= count; ++i) {
          points_.push_back(Point{variables_++, 0.0, s + f->length * i / count});
          const int b = static_cast<int>(points_.size()) - 1;
          // int_e EI ds by 3-point Gauss-Legendre (exact for EI linear on the element).
          const double s0 = f->length * (i - 1) / count;
          const double c = std::sqrt(0.6);
          const double integral =
              h / 2.0 *
              (5.0 / 9.0 * f->EI_at(s0 + h / 2.0 * (1.0 - c)) + 8.0 / 9.0 * f->EI_at(s0 + h / 2.0) +
               5.0 / 9.0 * f->EI_at(s0 + h / 2.0 * (1.0 + c)));
          elements_.push_back(Element{a, b, h, integral / (h * h), f->kappa0 * h});
          occurrences_.push_back(Occurrence{a, 0.0, h / 2.0, j});
          occurrences_.push_back(Occurrence{b, 0.0, h / 2.0, j});
          EI_max_ = std::max(EI_max_, integral / h);
          a = b;
        }
        current = a;
        extra = 0.0;
        last_flexible_point = a;
        node_angles_[j + 1] = NodeAngle{a, 0.0};
      } else {
        const auto& rigid = std::get<RigidSegment>(chain.segments[j]);
        extra += rigid.angle_offset;
        if (rigid.length > 0.0) occurrences_.push_back(Occurrence{current, extra, rigid.length, j});
        node_angles_[j + 1] = NodeAngle{current, extra};
      }
      s += std::visit([](const auto& seg) { return seg.length; }, chain.segments[j]);
    }
    length_ = s;
    if (mask_.theta) {
      // The last flexible node carries the prescribed tip angle (less the kinks after it): its
      // variable (the last one created) is removed.
      Point& last = points_[last_flexible_point];
      last.offset = target_.theta - extra;
      last.var = -1;
      --variables_;
      tip_point_ = last_flexible_point;
    }
    // Cumulative flexibility from the clamp (compression bound of second_variation.h).
    flexibility_.assign(variables_, 0.0);
    for (const Element& e : elements_) {
      const int va = points_[e.a].var, vb = points_[e.b].var;
      if (vb >= 0) flexibility_[vb] = (va >= 0 ? flexibility_[va] : 0.0) + 1.0 / e.k;
    }
    // B = sum k_e (e_b - e_a)(e_b - e_a)^T: tridiagonal in the variables (consecutive).
    B_diag_.assign(variables_, 0.0);
    B_off_.assign(std::max(variables_ - 1, 0), 0.0);
    for (const Element& e : elements_) {
      const int va = points_[e.a].var, vb = points_[e.b].var;
      if (va >= 0) B_diag_[va] += e.k;
      if (vb >= 0) B_diag_[vb] += e.k;
      if (va >= 0 && vb >= 0) {
        if (vb != va + 1) throw std::logic_error("discrete chain: variables not consecutive");
        B_off_[va] -= e.k;
      }
    }
    factor_B();
  }

  int size() const { return variables_; }
  double length() const { return length_; }
  double energy_scale() const { return EI_max_ / length_; }
  int flexible_elements() const { return static_cast<int>(elements_.size()); }
  const PrescribedMask& mask() const { return mask_; }

  // Arc lengths of the variables' nodes (just inside a segment's far end, on the flexible side
  // of a kink that may follow).
  std::vector<double> variable_stations() const {
    std::vector<double> s(variables_);
    for (const Element& e : elements_) {
      const int v = points_[e.b].var;
      if (v >= 0) s[v] = points_[e.b].s - 1e-9 * e.h;
    }
    return s;
  }

  double angle(const Eigen::VectorXd& q, int point) const {
    const Point& p = points_[point];
    return (p.var >= 0 ? q[p.var] : 0.0) + p.offset;
  }

  // theta(s) of the model at any arc length (linear between nodes; a rigid link's direction on
  // it): for starting a finer model.
  double angle_at(const Eigen::VectorXd& q, double s) const {
    for (const Element& e : elements_) {
      const double sa = points_[e.a].s, sb = points_[e.b].s;
      if (s >= sa - 1e-15 && s <= sb + 1e-15) {
        const double t = std::clamp((s - sa) / (sb - sa), 0.0, 1.0);
        return (1.0 - t) * angle(q, e.a) + t * angle(q, e.b);
      }
    }
    return 0.0;
  }

  // Total potential energy of the given loads (the support's work is constant on the constraint
  // manifold).
  double energy(const Eigen::VectorXd& q) const {
    double bending = 0.0;
    for (const Element& e : elements_) {
      const double turn = angle(q, e.b) - angle(q, e.a) - e.kappa_h;
      bending += 0.5 * e.k * turn * turn;
    }
    double work = 0.0;
    for (const Occurrence& o : occurrences_) {
      const double th = angle(q, o.point) + o.offset;
      work += o.weight * (segment_force_[o.segment].x() * std::cos(th) +
                          segment_force_[o.segment].y() * std::sin(th));
    }
    for (int node = 1; node < static_cast<int>(node_angles_.size()); ++node) {
      const double M = node_moment(node);
      if (M != 0.0) work += M * node_angle(q, node);
    }
    return bending - work;
  }

  // Gradient of the Lagrangian energy - R . r(L) with respect to every node angle (per point).
  std::vector<double> point_gradient(const Eigen::VectorXd& q, const Eigen::Vector2d& R) const {
    std::vector<double> g(points_.size(), 0.0);
    for (const Element& e : elements_) {
      const double turn = angle(q, e.b) - angle(q, e.a) - e.kappa_h;
      g[e.a] -= e.k * turn;
      g[e.b] += e.k * turn;
    }
    for (const Occurrence& o : occurrences_) {
      const double th = angle(q, o.point) + o.offset;
      const Eigen::Vector2d N = segment_force_[o.segment] + R;
      g[o.point] -= o.weight * (-N.x() * std::sin(th) + N.y() * std::cos(th));
    }
    for (int node = 1; node < static_cast<int>(node_angles_.size()); ++node) {
      g[node_angles_[node].point] -= node_moment(node);
    }
    return g;
  }

  Eigen::VectorXd to_variables(const std::vector<double>& per_point) const {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(variables_);
    for (std::size_t p = 0; p < points_.size(); ++p) {
      if (points_[p].var >= 0) g[points_[p].var] += per_point[p];
    }
    return g;
  }

  // Tip position and the rows d(x, y)(L)/dq.
  Eigen::Vector2d tip(const Eigen::VectorXd& q) const {
    Eigen::Vector2d r = Eigen::Vector2d::Zero();
    for (const Occurrence& o : occurrences_) {
      const double th = angle(q, o.point) + o.offset;
      r += o.weight * Eigen::Vector2d(std::cos(th), std::sin(th));
    }
    return r;
  }
  Eigen::MatrixXd tip_jacobian(const Eigen::VectorXd& q) const {
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(2, variables_);
    for (const Occurrence& o : occurrences_) {
      const int v = points_[o.point].var;
      if (v < 0) continue;
      const double th = angle(q, o.point) + o.offset;
      J(0, v) -= o.weight * std::sin(th);
      J(1, v) += o.weight * std::cos(th);
    }
    return J;
  }

  // The prescribed components: rows of the constraints, their values.
  Eigen::MatrixXd constraint_rows(const Eigen::VectorXd& q) const {
    const Eigen::MatrixXd J = tip_jacobian(q);
    Eigen::MatrixXd C(constraint_count(), variables_);
    int row = 0;
    if (mask_.x) C.row(row++) = J.row(0);
    if (mask_.y) C.row(row++) = J.row(1);
    return C;
  }
  Eigen::VectorXd constraint_values(const Eigen::VectorXd& q) const {
    const Eigen::Vector2d r = tip(q);
    Eigen::VectorXd c(constraint_count());
    int row = 0;
    if (mask_.x) c[row++] = r.x() - target_.x;
    if (mask_.y) c[row++] = r.y() - target_.y;
    return c;
  }
  int constraint_count() const { return (mask_.x ? 1 : 0) + (mask_.y ? 1 : 0); }
  // A vector of the prescribed components as a force (zeros elsewhere).
  Eigen::Vector2d as_force(const Eigen::VectorXd& multipliers) const {
    Eigen::Vector2d R = Eigen::Vector2d::Zero();
    int row = 0;
    if (mask_.x) R.x() = multipliers[row++];
    if (mask_.y) R.y() = multipliers[row++];
    return R;
  }

  // B^{-1} v (B = L D L^T factored once: B does not depend on q).
  Eigen::VectorXd solve_B(Eigen::VectorXd v) const {
    const int n = variables_;
    for (int i = 1; i < n; ++i) v[i] -= l_[i - 1] * v[i - 1];
    for (int i = 0; i < n; ++i) v[i] /= d_[i];
    for (int i = n - 1; i-- > 0;) v[i] -= l_[i] * v[i + 1];
    return v;
  }

  // The discrete second variation at q with the support reaction R, its constraint rows reduced
  // to independent ones (as the verdict does).
  DiscreteSecondVariation second_variation(const Eigen::VectorXd& q,
                                           const Eigen::Vector2d& R) const {
    DiscreteSecondVariation out;
    out.bending_diag = B_diag_;
    out.bending_off = B_off_;
    out.axial.assign(variables_, 0.0);
    for (const Occurrence& o : occurrences_) {
      const int v = points_[o.point].var;
      if (v < 0) continue;
      const double th = angle(q, o.point) + o.offset;
      const Eigen::Vector2d N = segment_force_[o.segment] + R;
      out.axial[v] += o.weight * (N.x() * std::cos(th) + N.y() * std::sin(th));
    }
    for (int v = 0; v < variables_; ++v) {
      out.compression_bound += std::max(0.0, -out.axial[v]) * flexibility_[v];
    }
    const Eigen::MatrixXd C = constraint_rows(q);
    // Rows normalised by the flexible length they weigh; vanishing (rms < 1e-10) or dependent
    // ones dropped, as the verdict does.
    std::vector<Eigen::VectorXd> kept;
    for (int r = 0; r < C.rows(); ++r) {
      Eigen::VectorXd row = C.row(r).transpose();
      const double rms = row.norm() / std::sqrt(std::max(1, variables_)) /
                         (length_ / std::max(1, flexible_elements()));
      if (!(rms > 1e-10)) continue;
      if (!kept.empty()) {
        const Eigen::VectorXd& first = kept.front();
        const double cosine = std::fabs(first.dot(row)) / (first.norm() * row.norm());
        if (1.0 - cosine < 1e-12) continue;
      }
      kept.push_back(row);
    }
    for (const Eigen::VectorXd& row : kept) {
      out.constraints.emplace_back(row.data(), row.data() + row.size());
    }
    return out;
  }

  // Moves q onto the constraints by Gauss-Newton steps of least B-norm. False when they cannot be
  // met (the steps stop shrinking).
  bool restore(Eigen::VectorXd& q) const {
    if (constraint_count() == 0) return true;
    const double tolerance = 1e-13 * length_;
    double previous = std::numeric_limits<double>::infinity();
    for (int iteration = 0; iteration < 60; ++iteration) {
      const Eigen::VectorXd c = constraint_values(q);
      const double size = c.cwiseAbs().maxCoeff();
      if (size <= tolerance) return true;
      if (!std::isfinite(size) || (iteration > 8 && size > 0.5 * previous)) return false;
      previous = size;
      const Eigen::MatrixXd C = constraint_rows(q);
      Eigen::MatrixXd BinvCt(variables_, C.rows());
      for (int r = 0; r < C.rows(); ++r) BinvCt.col(r) = solve_B(C.row(r).transpose());
      const Eigen::MatrixXd S = C * BinvCt;
      const Eigen::VectorXd y = S.completeOrthogonalDecomposition().solve(c);
      q -= BinvCt * y;
    }
    return constraint_values(q).cwiseAbs().maxCoeff() <= 1e3 * tolerance;
  }

  // Multipliers of the constraints (the support's reaction) that best balance the energy
  // gradient in the B^{-1} metric, and the remaining (tangential) gradient.
  std::pair<Eigen::Vector2d, Eigen::VectorXd> multipliers(const Eigen::VectorXd& q) const {
    const Eigen::VectorXd g0 =
        to_variables(point_gradient(q, Eigen::Vector2d::Zero()));  // energy gradient
    if (constraint_count() == 0) return {Eigen::Vector2d::Zero(), g0};
    const Eigen::MatrixXd C = constraint_rows(q);
    Eigen::MatrixXd BinvCt(variables_, C.rows());
    for (int r = 0; r < C.rows(); ++r) BinvCt.col(r) = solve_B(C.row(r).transpose());
    const Eigen::MatrixXd S = C * BinvCt;
    const Eigen::VectorXd mult = S.completeOrthogonalDecomposition().solve(BinvCt.transpose() * g0);
    // The energy's gradient is C^T mult at a constrained stationary point; the support exerts
    // that force on the tip (Lagrangian energy - R . (r(L) - r*)), so R = mult.
    return {as_force(mult), g0 - C.transpose() * mult};
  }

  // The support's moment (prescribed tip angle: the multiplier of theta(L) = theta*).
  double support_moment(const Eigen::VectorXd& q, const Eigen::Vector2d& R) const {
    if (tip_point_ < 0) return 0.0;
    return point_gradient(q, R)[tip_point_];
  }

  // Root unknowns of the shooting method at the model's equilibrium: m(0) from the statics of the
  // discrete shape, N(0) from the loads and the support's reaction (shooting_problem.h).
  std::vector<double> root_unknowns(const Eigen::VectorXd& q, const Eigen::Vector2d& R) const {
    const int n_segments = chain_.segment_count();
    std::vector<Eigen::Vector2d> span(n_segments, Eigen::Vector2d::Zero());
    for (const Occurrence& o : occurrences_) {
      const double th = angle(q, o.point) + o.offset;
      span[o.segment] += o.weight * Eigen::Vector2d(std::cos(th), std::sin(th));
    }
    // m(0) = m(L) + sum of node moments + int t x N ds (N piecewise constant).
    double m0 = chain_.tip_load.M + support_moment(q, R);
    for (const NodeLoad& load : chain_.node_loads) m0 += load.M;
    for (int j = 0; j < n_segments; ++j) {
      const Eigen::Vector2d N = segment_force_[j] + R;
      m0 += span[j].x() * N.y() - span[j].y() * N.x();
    }
    const Eigen::Vector2d N0 = segment_force_[0] + R;
    std::vector<double> z{m0};
    if (mask_.x) z.push_back(N0.x());
    if (mask_.y) z.push_back(N0.y());
    return z;
  }

 private:
  double node_moment(int node) const {
    double M = 0.0;
    if (node == chain_.segment_count()) M += chain_.tip_load.M;
    for (const NodeLoad& load : chain_.node_loads) {
      if (load.node == node) M += load.M;
    }
    return M;
  }
  double node_angle(const Eigen::VectorXd& q, int node) const {
    return angle(q, node_angles_[node].point) + node_angles_[node].offset;
  }
  void factor_B() {
    const int n = variables_;
    d_.assign(n, 0.0);
    l_.assign(std::max(n - 1, 0), 0.0);
    for (int i = 0; i < n; ++i) {
      double a = B_diag_[i];
      if (i > 0) {
        l_[i - 1] = B_off_[i - 1] / d_[i - 1];
        a -= l_[i - 1] * B_off_[i - 1];
      }
      d_[i] = a;
    }
  }

  SegmentChain chain_;
  PrescribedMask mask_;
  ChainPose target_;
  std::vector<Eigen::Vector2d> segment_force_;
  std::vector<Point> points_;
  std::vector<Occurrence> occurrences_;
  std::vector<Element> elements_;
  std::vector<NodeAngle> node_angles_;
  std::vector<double> flexibility_, B_diag_, B_off_, d_, l_;
  int variables_ = 0;
  int tip_point_ = -1;
  double length_ = 0.0;
  double EI_max_ = 0.0;
};

struct Descent {
  bool ok = false;
  Eigen::VectorXd q;
  Eigen::Vector2d R = Eigen::Vector2d::Zero();
  double energy = 0.0;
  double margin = 1.0;  // lowest eigenvalue of the discrete second variation at the end
  int iterations = 0;
  std::string why;  // when !ok
};

double max_abs(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }
double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

// Step 2 of stable_equilibrium.h from a point on the constraints; `sense` (+1 or -1) is the sense
// of the first step along the unstable direction.
Descent descend(const DiscreteChain& model,
                Eigen::VectorXd q,
                int sense,
                const StableEquilibriumOptions& options) {
  Descent out;
  const int n = model.size();
  const double critical = options.stability.critical_tolerance;
  const double energy_noise = 1e-14 * model.energy_scale();
  double previous_sense = sense;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    out.iterations = iteration;
    const auto [R, g] = model.multipliers(q);
    const DiscreteSecondVariation variation = model.second_variation(q, R);
    const PencilEigenvalue lowest = constrained_eigenvalue(variation, 1, 1e-11);
    const double lambda1 = lowest.exists ? lowest.value : 1.0;
    // Newton's step on the constraint manifold, the Hessian shifted by tau B where its lowest
    // eigenvalue is not clearly positive (the shifted one is then 0.05: a descent direction).
    const double tau = lambda1 > 1e-3 ? 0.0 : 0.05 - lambda1;
    std::vector<double> minus_g(n), step;
    for (int i = 0; i < n; ++i) minus_g[i] = -g[i];
    if (!solve_bordered(variation, 1.0 + tau, 1.0, minus_g, step)) {
      out.why = fmt::format("the Newton system is singular at descent step {}", iteration);
      return out;
    }
    Eigen::VectorXd d = Eigen::Map<const Eigen::VectorXd>(step.data(), n);
    const double newton_size = max_abs(step);
    if (lambda1 > critical && newton_size < 1e-11) {
      out.ok = true;
      out.q = q;
      out.R = R;
      out.energy = model.energy(q);
      out.margin = lambda1;
      return out;
    }
    // Along an unstable direction (and off a critical start): the eigenvector of the lowest
    // eigenvalue, in the sense that lowers the energy to first order (the given sense at the
    // start, where the gradient vanishes).
    if (lambda1 < -1e-9 || (iteration == 0 && lambda1 <= critical)) {
      std::vector<double> eta;
      try {
        eta = constrained_eigenvector(variation, lambda1);
      } catch (const NoConvergence& e) {
        out.why = e.what();
        return out;
      }
      const Eigen::Map<const Eigen::VectorXd> e(eta.data(), n);
      const double slope = g.dot(e);
      double s = previous_sense;
      if (iteration == 0) {
        s = sense;
      } else if (std::fabs(slope) > 1e-12 * model.energy_scale()) {
        s = slope > 0.0 ? -1.0 : 1.0;
      }
      previous_sense = s;
      d += s * options.unstable_step / max_abs(eta) * e;
    }
    const double size = max_abs(d);
    if (size > options.max_step) d *= options.max_step / size;
    const double energy = model.energy(q);
    bool accepted = false;
    double alpha = 1.0;
    if (tau == 0.0 && lambda1 > critical && newton_size < 1e-5) {
      // Newton's local (quadratic) regime: the energy changes by about the square of the step
      // times the stiffness, below its rounding; the step is taken as it is.
      Eigen::VectorXd trial = q + d;
      if (model.restore(trial)) {
        q = std::move(trial);
        accepted = true;
      }
    }
    for (int backtrack = 0; backtrack < 40 && !accepted; ++backtrack, alpha *= 0.5) {
      Eigen::VectorXd trial = q + alpha * d;
      if (!model.restore(trial)) continue;
      if (model.energy(trial) < energy - energy_noise) {
        q = std::move(trial);
        accepted = true;
      }
    }
    if (!accepted) {
      if (lambda1 > critical && newton_size < 1e-8) {
        // Converged to rounding: the energy cannot decrease measurably any more.
        out.ok = true;
        out.q = q;
        out.R = R;
        out.energy = energy;
        out.margin = lambda1;
        return out;
      }
      out.why = lambda1 <= critical
                    ? fmt::format(
                          "the energy does not decrease in either sense of the critical direction "
                          "(lowest eigenvalue {:.3g} of the discrete second variation): no "
                          "strictly stable equilibrium nearby",
                          lambda1)
                    : fmt::format(
                          "the energy stopped decreasing at descent step {} before the "
                          "gradient vanished (Newton step {:.3g} rad)",
                          iteration,
                          newton_size);
      return out;
    }
  }
  out.why = fmt::format("no minimum within {} descent steps", options.max_iterations);
  return out;
}

std::vector<int> elements_per_segment(const SegmentChain& chain,
                                      const Reaction& support,
                                      const StableEquilibriumOptions& options) {
  StabilityOptions stations = options.stability;
  stations.min_elements = std::max(stations.min_elements, options.min_elements);
  stations.max_elements = std::min(stations.max_elements, options.max_elements);
  const std::vector<double> s = stability_stations(chain, support, stations);
  std::vector<int> counts;
  double start = 0.0;
  for (const Segment& segment : chain.segments) {
    const double length = std::visit([](const auto& seg) { return seg.length; }, segment);
    if (std::holds_alternative<FlexibleSegment>(segment)) {
      const double tol = 1e-12 * chain.total_length();
      const auto inside = std::count_if(s.begin(), s.end(), [&](double x) {
        return x > start + tol && x <= start + length + tol;
      });
      counts.push_back(std::max(4, static_cast<int>(inside)));
    }
    start += length;
  }
  return counts;
}

Eigen::VectorXd sample_start(const DiscreteChain& model, const ShapeAtStations& start) {
  const std::vector<double> s = model.variable_stations();
  const std::vector<ShapePoint> shape = start(s);
  if (shape.size() != s.size()) {
    throw InvalidInput(
        fmt::format("stable equilibrium: the start shape returned {} points for {} arc lengths",
                    shape.size(),
                    s.size()));
  }
  Eigen::VectorXd q(model.size());
  for (int i = 0; i < model.size(); ++i) {
    require_finite(shape[i].theta, "stable equilibrium: the start shape's angle");
    q[i] = shape[i].theta;
  }
  return q;
}

struct Candidate {
  ShootingResult equilibrium;
  Stability stability;
  double energy = 0.0;
  int elements = 0;
  int sense = 1;
};

}  // namespace

void StableEquilibriumOptions::validate() const {
  if (min_elements < 4 || min_elements > max_elements || max_elements > 100000) {
    throw InvalidInput(fmt::format(
        "stable equilibrium: elements per segment must satisfy 4 <= min_elements ({}) <= "
        "max_elements ({}) <= 100000",
        min_elements,
        max_elements));
  }
  if (max_iterations < 1 || refinements < 0 || refinements > 6) {
    throw InvalidInput(fmt::format(
        "stable equilibrium: max_iterations ({}) must be >= 1 and refinements ({}) in [0, 6]",
        max_iterations,
        refinements));
  }
  if (!(max_step > 0.0 && max_step <= 2.0) || !(unstable_step > 0.0 && unstable_step <= 2.0)) {
    throw InvalidInput(
        fmt::format("stable equilibrium: max_step ({}) and unstable_step ({}) must be in (0, 2] "
                    "rad",
                    max_step,
                    unstable_step));
  }
  shooting.validate();
  stability.validate();
}

StableEquilibrium find_stable_equilibrium(const SegmentChain& chain,
                                          const ShapeAtStations& start,
                                          const Reaction& start_support_reaction,
                                          const StableEquilibriumOptions& options) {
  options.validate();
  chain.validate();
  if (chain.tip_load.follower != 0.0) {
    throw InvalidInput(
        "a stable equilibrium is a minimum of the potential energy, and a follower force has "
        "none (its stability is a dynamic question): --stable needs dead loads");
  }
  const bool flexible = std::any_of(chain.segments.begin(), chain.segments.end(), [](auto& s) {
    return std::holds_alternative<FlexibleSegment>(s);
  });
  if (!flexible) throw InvalidInput("stable equilibrium: the chain has no flexible segment");

  StableEquilibrium out;
  std::vector<int> counts = elements_per_segment(chain, start_support_reaction, options);
  const DiscreteChain base(chain, counts);
  Eigen::VectorXd q0 = sample_start(base, start);
  if (!base.restore(q0)) {
    out.message =
        "the start could not be brought onto the prescribed tip of the discrete model (the tip "
        "constraints are degenerate there)";
    return out;
  }
  out.start_energy = base.energy(q0);
  std::vector<Candidate> candidates;
  std::vector<std::string> failures;
  for (int sense : {1, -1}) {
    const Descent first = descend(base, q0, sense, options);
    out.iterations += first.iterations;
    if (!first.ok) {
      failures.push_back(fmt::format("{} sense: {}", sense > 0 ? "first" : "second", first.why));
      continue;
    }
    // Newton from the minimum; finer models where it does not converge.
    Descent current = first;
    const DiscreteChain* model = &base;
    std::optional<DiscreteChain> finer;
    std::vector<int> level_counts = counts;
    std::string why;
    for (int level = 0; level <= options.refinements; ++level) {
      if (level > 0) {
        for (int& c : level_counts) c = std::min(2 * c, 2 * options.max_elements);
        DiscreteChain next(chain, level_counts);
        Eigen::VectorXd q(next.size());
        const std::vector<double> s = next.variable_stations();
        for (int i = 0; i < next.size(); ++i) q[i] = model->angle_at(current.q, s[i]);
        finer.emplace(std::move(next));
        model = &*finer;
        if (!model->restore(q)) {
          why = "the refined model could not meet the prescribed tip";
          break;
        }
        const Descent refined = descend(*model, q, 1, options);
        out.iterations += refined.iterations;
        if (!refined.ok) {
          why = refined.why;
          break;
        }
        current = refined;
      }
      ShootingSolver::Options shooting = options.shooting;
      const ShootingResult r =
          ShootingSolver(shooting).solve_from(chain, model->root_unknowns(current.q, current.R));
      if (!r.converged()) {
        why = fmt::format(
            "Newton from the minimum of {} elements: {}", model->flexible_elements(), r.message);
        continue;
      }
      Stability verdict;
      try {
        verdict = equilibrium_stability(
            chain,
            tip_support_reaction(chain, r.tip_load),
            [&](const std::vector<double>& s) { return shooting_shape_at(chain, r, s, shooting); },
            options.stability);
      } catch (const NoConvergence& e) {
        why = fmt::format("the verdict of the converged equilibrium failed: {}", e.what());
        break;
      }
      if (!verdict.stable()) {
        why = fmt::format(
            "Newton from the minimum of {} elements converged to an equilibrium "
            "that is not stable ({})",
            model->flexible_elements(),
            verdict.message);
        continue;
      }
      candidates.push_back(
          Candidate{r, verdict, current.energy, model->flexible_elements(), sense});
      why.clear();
      break;
    }
    if (!why.empty()) {
      failures.push_back(fmt::format("{} sense: {}", sense > 0 ? "first" : "second", why));
    }
  }
  out.candidates = static_cast<int>(candidates.size());
  if (candidates.empty()) {
    out.message = fmt::format(
        "no stable equilibrium found by a descent of the potential energy from the start "
        "({})",
        fmt::join(failures, "; "));
    return out;
  }
  // The lower energy; a tie (mirror images) keeps the first sense.
  const Candidate* best = &candidates.front();
  for (const Candidate& c : candidates) {
    if (c.energy < best->energy - 1e-9 * std::max(1.0, std::fabs(best->energy)) *
                                      std::max(1.0, base.energy_scale())) {
      best = &c;
    }
  }
  out.equilibrium = best->equilibrium;
  out.stability = best->stability;
  out.energy = best->energy;
  out.elements = best->elements;
  out.set_converged(true);
  out.message = fmt::format(
      "descended the potential energy from the start along its unstable direction ({} of 2 "
      "senses reached a stable equilibrium{}), {} steps on a discrete model of {} elements; "
      "Newton (shooting) from its minimum converged; energy {:.6g} -> {:.6g}",
      candidates.size(),
      candidates.size() == 2 ? ", the one of lower energy returned" : "",
      out.iterations,
      best->elements,
      out.start_energy,
      out.energy);
  return out;
}

ShapeAtStations interpolated_shape(std::vector<ShapePoint> samples) {
  if (samples.size() < 2) throw InvalidInput("interpolated_shape: needs at least 2 samples");
  for (std::size_t i = 1; i < samples.size(); ++i) {
    if (!(samples[i].s >= samples[i - 1].s)) {
      throw InvalidInput("interpolated_shape: the samples' arc lengths must not decrease");
    }
  }
  return [samples = std::move(samples)](const std::vector<double>& s) {
    std::vector<ShapePoint> out;
    out.reserve(s.size());
    std::size_t j = 0;
    for (double x : s) {
      // The last sample pair [j, j + 1] with samples[j].s <= x (the far side at a repeated s).
      while (j + 2 < samples.size() && samples[j + 1].s <= x) ++j;
      while (j > 0 && samples[j].s > x) --j;
      const ShapePoint& a = samples[j];
      const ShapePoint& b = samples[j + 1];
      const double t = b.s > a.s ? std::clamp((x - a.s) / (b.s - a.s), 0.0, 1.0) : 1.0;
      out.push_back(ShapePoint{
          x, a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.theta + t * (b.theta - a.theta)});
    }
    return out;
  };
}

}  // namespace flexure
