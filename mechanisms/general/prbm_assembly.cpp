#include "flexure/mechanisms/general/prbm_assembly.h"

#include <algorithm>
#include <cmath>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

Eigen::Vector2d vec(Vec2 v) { return {v.x, v.y}; }

Eigen::Vector2d rotate(double phi, const Eigen::Vector2d& r) {
  const double c = std::cos(phi);
  const double s = std::sin(phi);
  return {c * r.x() - s * r.y(), s * r.x() + c * r.y()};
}

// d/dphi of R(phi) r.
Eigen::Vector2d rotate_rate(double phi, const Eigen::Vector2d& r) {
  const double c = std::cos(phi);
  const double s = std::sin(phi);
  return {-s * r.x() - c * r.y(), c * r.x() - s * r.y()};
}

// Step of the central differences of the Lagrangian's gradient, in scaled coordinates (lengths
// of order 1, angles in rad): truncation ~ h^2, rounding ~ 1e-16/h, both ~ 1e-10 or below.
constexpr double kHessianStep = 1e-6;

}  // namespace

PrbmAssembly::PrbmAssembly(const GeneralMechanism& mechanism, bool assemble_flexures)
    : mechanism_(mechanism) {
  mechanism_.validate();
  length_scale_ = mechanism_.size();
  const double L = length_scale_;
  input_ = mechanism_.input;

  // Described moving bodies, their reference points at their centroids.
  for (const Body& b : mechanism_.bodies) {
    if (b.name == "ground") {
      continue;
    }
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (const NamedPoint& p : b.points) {
      c += vec(p.position) / L;
    }
    if (!b.points.empty()) {
      c /= static_cast<double>(b.points.size());
    }
    bodies_.push_back({b.name, c});
  }
  described_bodies_ = static_cast<int>(bodies_.size());

  // Energy scale: the stiffest spring (N m; EI/l for a flexure), else the largest load's work over
  // L, else 1 J.
  double K = 0.0;
  for (const Flexure& f : mechanism_.flexures) {
    const Vec2 a = mechanism_.point(f.a);
    const Vec2 b = mechanism_.point(f.b);
    K = std::max(K, f.flexural_rigidity() / std::hypot(b.x - a.x, b.y - a.y));
  }
  for (const TorsionSpring& s : mechanism_.torsion_springs) {
    K = std::max(K, s.stiffness);
  }
  for (const LinearSpring& s : mechanism_.linear_springs) {
    K = std::max(K, s.stiffness * L * L);
  }
  if (!(K > 0.0)) {
    for (const DeadLoad& l : mechanism_.loads) {
      K = std::max({K, std::hypot(l.fx, l.fy) * L, std::fabs(l.moment)});
    }
  }
  energy_scale_ = K > 0.0 && std::isfinite(K) ? K : 1.0;

  auto scaled = [&](const PointRef& ref) {
    return Eigen::Vector2d(vec(mechanism_.point(ref)) / L);
  };
  auto item_name = [](std::string_view kind, const std::string& name) {
    return std::string(kind) + " '" + name + "'";
  };

  for (const Joint& j : mechanism_.joints) {
    Constraint c;
    c.kind = j.kind;
    c.a = make_point(body_index(j.a.body), scaled(j.a));
    c.b = make_point(body_index(j.b.body), scaled(j.b));
    c.axis_angle = j.axis_angle;
    constraints_.push_back(c);
    const int rows = j.kind == JointKind::kWeld ? 3 : 2;
    for (int i = 0; i < rows; ++i) {
      constraint_items_.push_back(item_name(joint_kind_name(j.kind), j.name));
    }
  }

  for (const Flexure& f : mechanism_.flexures) {
    if (!assemble_flexures) {
      break;
    }
    const Eigen::Vector2d a = scaled(f.a);
    const Eigen::Vector2d b = scaled(f.b);
    // The chord a -> b; a straight flexure's length. (A curved flexure's arc length enters its
    // spring and pivot below; solve_general_prbm has refused what the PRBM does not cover, and the
    // structural checks of the exact model need only the linkage's topology.)
    const double l = (b - a).norm();
    const Eigen::Vector2d u = (b - a) / l;
    const double arc_si = f.arc_length(l * L);
    const double l_si = arc_si;
    const double EI = f.flexural_rigidity();
    const int ia = body_index(f.a.body);
    const int ib = body_index(f.b.body);
    const std::string item = item_name("flexure", f.name);
    FlexureItems items;
    items.constraint = constraints_.size();
    items.torsion = torsions_.size();
    items.a = ia;
    items.b = ib;
    items.end_a = make_point(ia, a);
    items.end_b = make_point(ib, b);
    items.rest_a = std::atan2(u.y(), u.x()) + f.end_angle_from_chord(l * L, 0);
    items.rest_b = std::atan2(u.y(), u.x()) + f.end_angle_from_chord(l * L, 1);
    items.pinned = f.prbm == PrbmKind::kFixedPinned;
    auto add_pin = [&](const Pt& pa, const Pt& pb) {
      constraints_.push_back({JointKind::kPin, pa, pb, 0.0});
      constraint_items_.push_back(item);
      constraint_items_.push_back(item);
    };
    auto add_link = [&](const Eigen::Vector2d& p1, const Eigen::Vector2d& p2) {
      bodies_.push_back({"flexure '" + f.name + "' PRB link", (p1 + p2) / 2.0});
      return static_cast<int>(bodies_.size()) - 1;
    };
    switch (f.prbm) {
      case PrbmKind::kSmallLengthPivot: {
        // Howell §5.1: the pivot at mid-flexure (geometry().pivot_x = 1/2), K = EI/l (eq. 5.14).
        const SmallLengthFlexuralPivot element(0.0);
        const Eigen::Vector2d pivot = a + element.geometry().pivot_x * l * u;
        add_pin(make_point(ia, pivot), make_point(ib, pivot));
        torsions_.push_back(
            {ia, ib, element.stiffness_coefficient() * EI / l_si / energy_scale_, 0.0});
        break;
      }
      case PrbmKind::kFixedPinned: {
        const double kappa0 = std::fabs(f.curvature * arc_si);
        if (f.curved() && kappa0 <= 2.0) {
          // Howell §5.5: the initially curved cantilever. The pivot sits (1 - gamma) l along the
          // clamp's tangent (eq. 5.119, gamma measured as if the beam were straight), the link
          // joins it to the tip (length rho l, at Theta_i when unloaded: eqs. 5.115-5.118), and
          // K = rho K_Theta EI/l acts on Theta - Theta_i (eqs. 5.124-5.127): its spring is
          // relaxed in the described configuration. Table 5.2's gamma and K_Theta for |kappa0|
          // (a negative curvature is the mirror image).
          const InitiallyCurvedCantilever element(CurvedCantileverConstants::from_table(kappa0));
          const Eigen::Vector2d t0 = rotate(f.end_angle_from_chord(l * L, 0), u);
          const Eigen::Vector2d pivot = a + element.geometry().pivot_x * (arc_si / L) * t0;
          const int link = add_link(pivot, b);
          add_pin(make_point(ia, pivot), make_point(link, pivot));
          add_pin(make_point(link, b), make_point(ib, b));
          torsions_.push_back(
              {ia, link, element.stiffness_coefficient() * EI / l_si / energy_scale_, 0.0});
          break;
        }
        // Howell §5.2: a link gamma l from the pivot (1 - gamma) l from the clamp to the pinned
        // far end, K = gamma K_Theta EI/l (eq. 5.72), Howell's average constants.
        const FixedPinnedSegment& element = howell_average_fixed_pinned();
        const Eigen::Vector2d pivot = a + element.geometry().pivot_x * l * u;
        const int link = add_link(pivot, b);
        add_pin(make_point(ia, pivot), make_point(link, pivot));
        add_pin(make_point(link, b), make_point(ib, b));
        torsions_.push_back(
            {ia, link, element.stiffness_coefficient() * EI / l_si / energy_scale_, 0.0});
        break;
      }
      case PrbmKind::kFixedGuided: {
        // Howell §5.3: two pivots (1 - gamma) l/2 from the ends joined by a link gamma l, a spring
        // 2 gamma K_Theta EI/l at each (eq. 5.105). In a general mechanism the far body may turn:
        // each spring then carries its own relative rotation.
        const FixedGuidedSegment element;
        const PrbGeometry g = element.geometry();
        const Eigen::Vector2d p1 = a + g.pivot_x * l * u;
        const Eigen::Vector2d p2 = p1 + g.link_length * l * u;
        const int link = add_link(p1, p2);
        add_pin(make_point(ia, p1), make_point(link, p1));
        add_pin(make_point(link, p2), make_point(ib, p2));
        const double k = element.stiffness_coefficient() * EI / l_si / energy_scale_;
        torsions_.push_back({ia, link, k, 0.0});
        torsions_.push_back({link, ib, k, 0.0});
        break;
      }
    }
    items.constraints = constraints_.size() - items.constraint;
    items.torsions = torsions_.size() - items.torsion;
    flexure_items_.push_back(items);
  }
  constraint_rows_ = static_cast<int>(constraint_items_.size());
  int row = 0;
  for (const Constraint& c : constraints_) {
    constraint_first_row_.push_back(row);
    row += c.kind == JointKind::kPin ? 2 : (c.kind == JointKind::kWeld ? 3 : 2);
  }

  for (const TorsionSpring& s : mechanism_.torsion_springs) {
    torsions_.push_back(
        {body_index(s.body_a), body_index(s.body_b), s.stiffness / energy_scale_, s.rest_angle});
  }
  for (const LinearSpring& s : mechanism_.linear_springs) {
    const Eigen::Vector2d a = scaled(s.a);
    const Eigen::Vector2d b = scaled(s.b);
    linears_.push_back({make_point(body_index(s.a.body), a),
                        make_point(body_index(s.b.body), b),
                        s.stiffness * L * L / energy_scale_,
                        s.rest_length < 0.0 ? (b - a).norm() : s.rest_length / L});
  }
  for (const DeadLoad& l : mechanism_.loads) {
    loads_.push_back({make_point(body_index(l.at.body), scaled(l.at)),
                      Eigen::Vector2d(l.fx, l.fy) * L / energy_scale_,
                      l.moment / energy_scale_});
  }

  const int ib = body_index(input_.body);
  input_point_ = make_point(ib, scaled({input_.body, input_.point}));
  if (input_.coordinate == InputCoordinate::kAngle) {
    const Eigen::Vector2d d =
        scaled({input_.body, input_.point_to}) - scaled({input_.body, input_.point});
    input_angle0_ = std::atan2(d.y(), d.x());
  }
}

std::vector<std::string> PrbmAssembly::body_names() const {
  std::vector<std::string> names;
  for (const Frame& f : bodies_) {
    names.push_back(f.name);
  }
  return names;
}

int PrbmAssembly::body_index(const std::string& name) const {
  if (name == "ground") {
    return -1;
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (bodies_[i].name == name) {
      return static_cast<int>(i);
    }
  }
  throw InvalidInput("unknown body '" + name + "'");
}

PrbmAssembly::Pt PrbmAssembly::make_point(int body, const Eigen::Vector2d& p) const {
  Pt pt;
  pt.body = body;
  pt.c0 = body < 0 ? Eigen::Vector2d::Zero() : bodies_[static_cast<std::size_t>(body)].c0;
  pt.r = p - pt.c0;
  return pt;
}

double PrbmAssembly::phi(const Eigen::VectorXd& q, int body) const {
  return body < 0 ? 0.0 : q[3 * body + 2];
}

Eigen::Vector2d PrbmAssembly::position(const Eigen::VectorXd& q, const Pt& p) const {
  if (p.body < 0) {
    return p.c0 + p.r;
  }
  const int o = 3 * p.body;
  return p.c0 + Eigen::Vector2d(q[o], q[o + 1]) + rotate(q[o + 2], p.r);
}

void PrbmAssembly::add_position_gradient(const Eigen::VectorXd& q,
                                         const Pt& p,
                                         const Eigen::Vector2d& weight,
                                         RowRef row) const {
  if (p.body < 0) {
    return;
  }
  const int o = 3 * p.body;
  row[o] += weight.x();
  row[o + 1] += weight.y();
  row[o + 2] += weight.dot(rotate_rate(q[o + 2], p.r));
}

void PrbmAssembly::add_phi_gradient(int body, double weight, RowRef row) const {
  if (body >= 0) {
    row[3 * body + 2] += weight;
  }
}

Eigen::VectorXd PrbmAssembly::constraints(const Eigen::VectorXd& q) const {
  Eigen::VectorXd g(constraint_rows_);
  int k = 0;
  for (const Constraint& c : constraints_) {
    const Eigen::Vector2d e = position(q, c.b) - position(q, c.a);
    if (c.kind == JointKind::kSlider) {
      const Eigen::Vector2d n =
          rotate(phi(q, c.a.body), {-std::sin(c.axis_angle), std::cos(c.axis_angle)});
      g[k++] = n.dot(e);
      g[k++] = phi(q, c.b.body) - phi(q, c.a.body);
    } else {
      g[k++] = e.x();
      g[k++] = e.y();
      if (c.kind == JointKind::kWeld) {
        g[k++] = phi(q, c.b.body) - phi(q, c.a.body);
      }
    }
  }
  return g;
}

Eigen::MatrixXd PrbmAssembly::constraint_jacobian(const Eigen::VectorXd& q) const {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(constraint_rows_, coordinate_count());
  int k = 0;
  for (const Constraint& c : constraints_) {
    if (c.kind == JointKind::kSlider) {
      const Eigen::Vector2d n0(-std::sin(c.axis_angle), std::cos(c.axis_angle));
      const double pa = phi(q, c.a.body);
      const Eigen::Vector2d n = rotate(pa, n0);
      const Eigen::Vector2d e = position(q, c.b) - position(q, c.a);
      add_position_gradient(q, c.b, n, J.row(k));
      add_position_gradient(q, c.a, -n, J.row(k));
      add_phi_gradient(c.a.body, rotate_rate(pa, n0).dot(e), J.row(k));
      ++k;
      add_phi_gradient(c.b.body, 1.0, J.row(k));
      add_phi_gradient(c.a.body, -1.0, J.row(k));
      ++k;
    } else {
      for (int axis = 0; axis < 2; ++axis) {
        const Eigen::Vector2d w = axis == 0 ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(0, 1);
        add_position_gradient(q, c.b, w, J.row(k));
        add_position_gradient(q, c.a, -w, J.row(k));
        ++k;
      }
      if (c.kind == JointKind::kWeld) {
        add_phi_gradient(c.b.body, 1.0, J.row(k));
        add_phi_gradient(c.a.body, -1.0, J.row(k));
        ++k;
      }
    }
  }
  return J;
}

double PrbmAssembly::spring_energy(const Eigen::VectorXd& q) const {
  double V = 0.0;
  for (const Torsion& t : torsions_) {
    const double psi = phi(q, t.b) - phi(q, t.a) - t.rest;
    V += 0.5 * t.k * psi * psi;
  }
  for (const Linear& s : linears_) {
    const double stretch = (position(q, s.b) - position(q, s.a)).norm() - s.rest;
    V += 0.5 * s.k * stretch * stretch;
  }
  return V;
}

double PrbmAssembly::energy(const Eigen::VectorXd& q) const {
  double V = spring_energy(q);
  for (const Load& l : loads_) {
    V -= l.force.dot(position(q, l.at)) + l.moment * phi(q, l.at.body);
  }
  return V;
}

Eigen::VectorXd PrbmAssembly::energy_gradient(const Eigen::VectorXd& q) const {
  Eigen::RowVectorXd grad = Eigen::RowVectorXd::Zero(coordinate_count());
  for (const Torsion& t : torsions_) {
    const double psi = phi(q, t.b) - phi(q, t.a) - t.rest;
    add_phi_gradient(t.b, t.k * psi, grad);
    add_phi_gradient(t.a, -t.k * psi, grad);
  }
  for (const Linear& s : linears_) {
    const Eigen::Vector2d d = position(q, s.b) - position(q, s.a);
    const double length = d.norm();
    if (length > 0.0) {
      const Eigen::Vector2d w = s.k * (length - s.rest) * d / length;
      add_position_gradient(q, s.b, w, grad);
      add_position_gradient(q, s.a, -w, grad);
    }
  }
  for (const Load& l : loads_) {
    add_position_gradient(q, l.at, -l.force, grad);
    add_phi_gradient(l.at.body, -l.moment, grad);
  }
  return grad.transpose();
}

Eigen::MatrixXd PrbmAssembly::unloaded_stiffness(const Eigen::VectorXd& q) const {
  const int n = coordinate_count();
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
  for (const Torsion& t : torsions_) {
    Eigen::RowVectorXd g = Eigen::RowVectorXd::Zero(n);
    add_phi_gradient(t.b, 1.0, g);
    add_phi_gradient(t.a, -1.0, g);
    B += t.k * g.transpose() * g;
  }
  for (const Linear& s : linears_) {
    const Eigen::Vector2d d = position(q, s.b) - position(q, s.a);
    const double length = d.norm();
    if (length > 0.0) {
      Eigen::RowVectorXd g = Eigen::RowVectorXd::Zero(n);
      add_position_gradient(q, s.b, d / length, g);
      add_position_gradient(q, s.a, -d / length, g);
      B += s.k * g.transpose() * g;
    }
  }
  return B;
}

double PrbmAssembly::input(const Eigen::VectorXd& q) const {
  switch (input_.coordinate) {
    case InputCoordinate::kX:
      return position(q, input_point_).x();
    case InputCoordinate::kY:
      return position(q, input_point_).y();
    case InputCoordinate::kAngle:
      return input_angle0_ + phi(q, input_point_.body);
  }
  return 0.0;
}

Eigen::VectorXd PrbmAssembly::input_gradient(const Eigen::VectorXd& q) const {
  Eigen::RowVectorXd grad = Eigen::RowVectorXd::Zero(coordinate_count());
  switch (input_.coordinate) {
    case InputCoordinate::kX:
      add_position_gradient(q, input_point_, {1.0, 0.0}, grad);
      break;
    case InputCoordinate::kY:
      add_position_gradient(q, input_point_, {0.0, 1.0}, grad);
      break;
    case InputCoordinate::kAngle:
      add_phi_gradient(input_point_.body, 1.0, grad);
      break;
  }
  return grad.transpose();
}

Eigen::VectorXd PrbmAssembly::lagrangian_gradient(const Eigen::VectorXd& q,
                                                  const Eigen::VectorXd& mu,
                                                  double lambda) const {
  return energy_gradient(q) - lambda * input_gradient(q) - constraint_jacobian(q).transpose() * mu;
}

Eigen::MatrixXd PrbmAssembly::lagrangian_hessian(const Eigen::VectorXd& q,
                                                 const Eigen::VectorXd& mu,
                                                 double lambda) const {
  const int n = coordinate_count();
  Eigen::MatrixXd H(n, n);
  Eigen::VectorXd qp = q;
  for (int j = 0; j < n; ++j) {
    qp[j] = q[j] + kHessianStep;
    const Eigen::VectorXd gp = lagrangian_gradient(qp, mu, lambda);
    qp[j] = q[j] - kHessianStep;
    const Eigen::VectorXd gm = lagrangian_gradient(qp, mu, lambda);
    qp[j] = q[j];
    H.col(j) = (gp - gm) / (2.0 * kHessianStep);
  }
  return 0.5 * (H + H.transpose());
}

Vec2 PrbmAssembly::point_position_si(const Eigen::VectorXd& q, const PointRef& ref) const {
  const Pt p = make_point(body_index(ref.body), vec(mechanism_.point(ref)) / length_scale_);
  const Eigen::Vector2d x = position(q, p) * length_scale_;
  return {x.x(), x.y()};
}

}  // namespace flexure::mechanism::general

namespace flexure::mechanism::general {

Eigen::Vector2d PrbmAssembly::point_scaled(const Eigen::VectorXd& q, const PointRef& ref) const {
  const Vec2 p = mechanism_.point(ref);
  return position(q, make_point(body_index(ref.body), Eigen::Vector2d(p.x, p.y) / length_scale_));
}

double PrbmAssembly::body_rotation(const Eigen::VectorXd& q, const std::string& body) const {
  return phi(q, body_index(body));
}

void PrbmAssembly::add_wrench(const Eigen::VectorXd& q,
                              const PointRef& ref,
                              const Eigen::Vector2d& force,
                              double moment,
                              Eigen::VectorXd& generalized) const {
  const Vec2 p = mechanism_.point(ref);
  const Pt pt = make_point(body_index(ref.body), Eigen::Vector2d(p.x, p.y) / length_scale_);
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(coordinate_count());
  add_position_gradient(q, pt, force, row);
  add_phi_gradient(pt.body, moment, row);
  generalized += row.transpose();
}

}  // namespace flexure::mechanism::general

namespace flexure::mechanism::general {
namespace {
double cross(const Eigen::Vector2d& r, const Eigen::Vector2d& f) {
  return r.x() * f.y() - r.y() * f.x();
}
}  // namespace

Eigen::Vector3d PrbmAssembly::constraint_wrench(
    const Eigen::VectorXd& q, const Eigen::VectorXd& mu, std::size_t ci, int row, int body) const {
  // J_g^T mu is the generalised force of the constraints on the bodies (the Lagrangian's
  // gradient grad V - J_g^T mu = 0): each row's multiplier times the row's gradient. A pin's rows
  // (p_b - p_a) give body b the force mu at p_b and body a -mu at p_a; a slider's first row (the
  // distance of p_b from a's line, along n) gives b mu n at p_b and a -mu n at p_b too (its
  // dependence on phi_a is the moment arm from p_a to p_b); a relative-angle row gives b the moment
  // mu and a -mu.
  const Constraint& c = constraints_[ci];
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  const double sign = body == c.b.body ? 1.0 : (body == c.a.body ? -1.0 : 0.0);
  if (sign == 0.0) return w;
  const Eigen::Vector2d pb = position(q, c.b), pa = position(q, c.a);
  Eigen::Vector2d f;
  Eigen::Vector2d at;
  double moment = 0.0;
  if (c.kind == JointKind::kSlider) {
    const Eigen::Vector2d n =
        rotate(phi(q, c.a.body), {-std::sin(c.axis_angle), std::cos(c.axis_angle)});
    f = mu[row] * n;
    at = pb;
    moment = mu[row + 1];
  } else {
    f = Eigen::Vector2d(mu[row], mu[row + 1]);
    at = sign > 0.0 ? pb : pa;
    if (c.kind == JointKind::kWeld) moment = mu[row + 2];
  }
  f *= sign;
  moment *= sign;
  w << f.x(), f.y(), moment + cross(at, f);
  return w;
}

double PrbmAssembly::torsion_moment(const Eigen::VectorXd& q, std::size_t ti, int body) const {
  // V = k psi^2/2, psi = phi_b - phi_a - rest: the spring turns b by -k psi and a by +k psi.
  const Torsion& t = torsions_[ti];
  const double psi = phi(q, t.b) - phi(q, t.a) - t.rest;
  if (body == t.b) return -t.k * psi;
  if (body == t.a) return t.k * psi;
  return 0.0;
}

Eigen::Vector3d PrbmAssembly::joint_reaction_si(const Eigen::VectorXd& q,
                                                const Eigen::VectorXd& mu,
                                                int j) const {
  const std::size_t ci = static_cast<std::size_t>(j);
  const Constraint& c = constraints_.at(ci);
  const Eigen::Vector3d w = constraint_wrench(q, mu, ci, constraint_first_row_[ci], c.b.body);
  const Eigen::Vector2d pb = position(q, c.b);
  const Eigen::Vector2d f(w[0], w[1]);
  const double K = energy_scale_, L = length_scale_;
  return {f.x() * K / L, f.y() * K / L, (w[2] - cross(pb, f)) * K};
}

Eigen::Vector3d PrbmAssembly::flexure_end_load_si(const Eigen::VectorXd& q,
                                                  const Eigen::VectorXd& mu,
                                                  int i,
                                                  int end) const {
  const FlexureItems& it = flexure_items_.at(static_cast<std::size_t>(i));
  const int body = end == 0 ? it.a : it.b;
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (std::size_t c = it.constraint; c < it.constraint + it.constraints; ++c) {
    w += constraint_wrench(q, mu, c, constraint_first_row_[c], body);
  }
  for (std::size_t t = it.torsion; t < it.torsion + it.torsions; ++t) {
    w[2] += torsion_moment(q, t, body);
  }
  const Eigen::Vector2d p = position(q, end == 0 ? it.end_a : it.end_b);
  const Eigen::Vector2d f(w[0], w[1]);
  const double K = energy_scale_, L = length_scale_;
  return {f.x() * K / L, f.y() * K / L, (w[2] - cross(p, f)) * K};
}

std::vector<Vec2> PrbmAssembly::flexure_prb_points_si(const Eigen::VectorXd& q, int i) const {
  const FlexureItems& it = flexure_items_.at(static_cast<std::size_t>(i));
  std::vector<Vec2> out;
  auto push = [&](const Eigen::Vector2d& p) {
    out.push_back({p.x() * length_scale_, p.y() * length_scale_});
  };
  push(position(q, it.end_a));
  // Each PRB pin of the flexure joins the linkage at its point (the pivots, then end b's pin for
  // a fixed-pinned flexure, which coincides with end b).
  for (std::size_t c = it.constraint; c < it.constraint + it.constraints; ++c) {
    push(position(q, constraints_[c].b));
  }
  const Eigen::Vector2d b = position(q, it.end_b);
  if ((out.back().x - b.x() * length_scale_) != 0.0 ||
      (out.back().y - b.y() * length_scale_) != 0.0) {
    push(b);
  }
  return out;
}

double PrbmAssembly::flexure_end_angle(const Eigen::VectorXd& q, int i, int end) const {
  const FlexureItems& it = flexure_items_.at(static_cast<std::size_t>(i));
  if (end == 0) return it.rest_a + phi(q, it.a);
  if (!it.pinned) return it.rest_b + phi(q, it.b);
  // Pinned far end: the last PRB link (from the pivot to end b) gives the tangent.
  const std::vector<Vec2> p = flexure_prb_points_si(q, i);
  const Vec2& p1 = p[p.size() - 2];
  const Vec2& p2 = p.back();
  return std::atan2(p2.y - p1.y, p2.x - p1.x);
}

Eigen::Vector3d PrbmAssembly::ground_reaction_si(const Eigen::VectorXd& q,
                                                 const Eigen::VectorXd& mu) const {
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  // The load on the ground, then negated: the load the ground puts on the mechanism.
  for (std::size_t c = 0; c < constraints_.size(); ++c) {
    w += constraint_wrench(q, mu, c, constraint_first_row_[c], -1);
  }
  for (std::size_t t = 0; t < torsions_.size(); ++t) {
    w[2] += torsion_moment(q, t, -1);
  }
  for (const Linear& s : linears_) {
    const Eigen::Vector2d d = position(q, s.b) - position(q, s.a);
    const double length = d.norm();
    if (!(length > 0.0)) continue;
    // V = k (|d| - rest)^2/2: the spring pulls b by -k (|d| - rest) d/|d| and a by the opposite.
    const Eigen::Vector2d fb = -s.k * (length - s.rest) * d / length;
    if (s.a.body < 0) {
      w.head<2>() -= fb;
      w[2] += cross(position(q, s.a), -fb);
    }
    if (s.b.body < 0) {
      w.head<2>() += fb;
      w[2] += cross(position(q, s.b), fb);
    }
  }
  const double K = energy_scale_, L = length_scale_;
  return {-w[0] * K / L, -w[1] * K / L, -w[2] * K};
}

}  // namespace flexure::mechanism::general
