// Frictionless contact with a rigid circle (wrap from the clamp) or a straight stop (tip contact):
// see rigid_contact.h and docs/contact.md for the equations.
#include "flexure/solver/shooting/rigid_contact.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <variant>

#include "flexure/solver/chain_model/held_stability.h"
#include "flexure/solver/chain_model/second_variation.h"
#include "flexure/solver/common/enum_names.h"
#include "flexure/solver/common/scalar_root.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

const char* to_string(ContactSurfaceType type) {
  return type == ContactSurfaceType::kCircle ? "circle" : "line";
}

namespace {
constexpr std::array<const char*, 4> kContactEventKindNames = {
    "landing", "lift-off", "line-contact", "tip-contact"};
constexpr std::array<const char*, 5> kContactKindNames = {"none", "wrap", "tip", "point", "line"};
}  // namespace

const char* to_string(ContactEventKind kind) { return enum_name(kContactEventKindNames, kind); }

ContactEventKind contact_event_kind_from_string(std::string_view name) {
  return enum_from_name<ContactEventKind>(kContactEventKindNames, name, "contact event kind");
}

const char* to_string(ContactKind kind) { return enum_name(kContactKindNames, kind); }

ContactKind contact_kind_from_string(std::string_view name) {
  return enum_from_name<ContactKind>(kContactKindNames, name, "contact kind");
}

void RigidContactSolver::Options::validate() const {
  shooting.validate();
  if (steps < 1 || steps > 100000) {
    throw InvalidInput(fmt::format("contact steps must be in [1, 100000] (got {})", steps));
  }
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw InvalidInput(fmt::format("contact option {} must be positive and finite", name));
    }
  };
  positive(event_tolerance, "event_tolerance");
  positive(contact_tolerance, "contact_tolerance");
  positive(gap_tolerance, "gap_tolerance");
  if (gap_samples < 3) throw InvalidInput("contact option gap_samples must be at least 3");
  if (shape_points < 0 || shape_points == 1) {
    throw InvalidInput("contact option shape_points must be 0 or at least 2");
  }
}

namespace {

using V2 = Eigen::Vector2d;

V2 rotate(double angle, const V2& v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return V2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

// The chain's dead tip and node forces turned by `angle` (into a frame turned by -angle); moments
// and the follower force do not change.
void rotate_dead_forces(SegmentChain& chain, double angle) {
  const V2 tip = rotate(angle, V2(chain.tip_load.Fx, chain.tip_load.Fy));
  chain.tip_load.Fx = tip.x();
  chain.tip_load.Fy = tip.y();
  for (NodeLoad& load : chain.node_loads) {
    const V2 f = rotate(angle, V2(load.Fx, load.Fy));
    load.Fx = f.x();
    load.Fy = f.y();
  }
}

// A solve that the contact model cannot complete (non-convergence of a free-span solve, no
// separation point): reported as the result's message.
struct ContactFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Newton's method for the small contact systems (the interior point's (s, P, phi), the line
// contact's (a, R_a)): a finite-difference Jacobian, one residual per column with step h(z)[c]
// (a negative step differences backwards), a full-pivot LU step, and backtracking until |g|
// falls by the Armijo factor (1 - 1e-4 step). `project` keeps a trial in the unknowns' domain;
// a trial whose residual throws ContactFailure is halved again. Returns true when every
// |g[i]| < tol[i] (z and g then hold the solution), false when a step found no decrease or 60
// steps passed; throws ContactFailure(`singular`) on a non-finite step.
template <int N, class Residual, class StepSizes, class Project>
bool damped_newton(Residual&& residual,
                   StepSizes&& steps,
                   Project&& project,
                   const Eigen::Matrix<double, N, 1>& tol,
                   const char* singular,
                   Eigen::Matrix<double, N, 1>& z,
                   Eigen::Matrix<double, N, 1>& g) {
  using Vec = Eigen::Matrix<double, N, 1>;
  g = residual(z);
  for (int it = 0; it < 60; ++it) {
    if ((g.array().abs() < tol.array()).all()) return true;
    const Vec h = steps(z);
    Eigen::Matrix<double, N, N> J;
    for (int c = 0; c < N; ++c) {
      Vec zc = z;
      zc[c] += h[c];
      J.col(c) = (residual(zc) - g) / h[c];
    }
    const Vec dz = J.fullPivLu().solve(-g);
    if (!dz.allFinite()) throw ContactFailure(singular);
    double step = 1.0;
    bool accepted = false;
    for (int ls = 0; ls < 30; ++ls, step *= 0.5) {
      Vec trial = z + step * dz;
      project(trial);
      Vec gt;
      try {
        gt = residual(trial);
      } catch (const ContactFailure&) {
        continue;
      }
      if (gt.norm() < (1.0 - 1e-4 * step) * g.norm()) {
        z = trial;
        g = gt;
        accepted = true;
        break;
      }
    }
    if (!accepted) return false;
  }
  return false;
}

enum class ContactMode { kNone, kWrap, kTip, kPoint, kLying };

class ContactRun {
 public:
  ContactRun(const SegmentChain& chain,
             const RigidSurface& surface,
             const TipLoad& start,
             const RigidContactSolver::Options& options)
      : full_(chain), surface_(surface), start_(start), options_(options) {
    plain_options_ = options.shooting;
    plain_options_.shape_points = 0;
    sampled_options_ = options.shooting;
    sampled_options_.shape_points = options.gap_samples;
    length_ = chain.total_length();
    validate();
  }

  ContactResult run();

  // Several surfaces (RigidContactSolver::solve with a list): this run's surface is contact
  // `self` (1-based, for messages); the others must stay clear of the beam at every step.
  void set_others(int self, std::vector<RigidSurface> others, std::vector<int> ids) {
    self_id_ = self;
    others_ = std::move(others);
    other_ids_ = std::move(ids);
  }

 private:
  void validate();
  // The smallest gap of a root-frame shape to the other surfaces (other_gap_, where and which).
  void note_other_gaps(const std::vector<ShapePoint>& shape);
  std::string surface_name() const;
  SegmentChain chain_at(double lambda) const;
  ShootingResult shoot(const SegmentChain& chain, bool sampled);
  // psi(lambda) < 0 where contact holds (rigid_contact.h); also the free solution's minimum gap.
  double indicator(double lambda, double* interior_gap = nullptr);
  double gap_of(const V2& r) const;
  // EI_min / L^2 over the flexible segments: the force scale of the contact systems' Newton
  // steps.
  double most_flexible_force_scale() const;
  // The smallest gap of a sampled shape (and where it is: min_gap_s_).
  double min_gap(const std::vector<ShapePoint>& shape, bool skip_last, bool skip_root);
  // The contact held now, in words (for the message of a second contact).
  std::string contact_description(double variable) const;

  // Circle: the wrap pose at s, the free span solved from s, its curvature residual.
  ChainPose wrap_pose(double s) const;
  SegmentChain span_chain(const SegmentChain& chain, double s_c) const;
  double curvature_residual(const SegmentChain& chain, double s_c);
  double solve_wrap(const SegmentChain& chain, double guess);
  // Line: the tip gap with a normal reaction R_n at the tip.
  SegmentChain with_reaction(const SegmentChain& chain, double Rn) const;
  double tip_gap(const SegmentChain& chain, double Rn);
  double solve_tip_reaction(const SegmentChain& chain, double guess);

  // Interior point contact: the chain cut at s with the contact force P grad g there, and the
  // residuals (gap, tangency) at the contact point.
  V2 gap_gradient(const V2& r) const;
  SegmentChain split_chain(const SegmentChain& chain, double s, const V2& force) const;
  Eigen::Vector3d point_residual(const SegmentChain& chain,
                                 const Eigen::Vector3d& z,
                                 ChainPose* pose);
  void solve_point(const SegmentChain& chain);
  // The mode of a contact that begins at load factor lambda (free solution penetrating there).
  ContactMode landing_mode(double lambda);

  // Line contact (docs/contact.md, section 3): the beam lies on the stop over [a, L] (in the last
  // segment). The lying part carries its loads to the stop directly (m = 0 there); the free span
  // [0, a] is the chain cut at a under its own loads and the end force N_t tau + R_a nu, and
  // (a, R_a) solve gap(r(a)) = 0, t(a) . nu = 0.
  struct LyingStatics {
    double N_t = 0.0;           // axial force of the lying part at a+ (along tau)
    double tip_reaction = 0.0;  // the stop's concentrated reaction at the tip, -F_tip . nu
    double pressure = 0.0;      // the stop's line pressure on the lying part, -(q + q_f n) . nu
  };
  void check_lying(const SegmentChain& chain) const;
  LyingStatics lying_statics(const SegmentChain& chain, double a) const;
  SegmentChain lying_span(const SegmentChain& chain, double a, double R) const;
  Eigen::Vector2d lying_residual(const SegmentChain& chain, double a, double R);
  void solve_lying(const SegmentChain& chain);
  // The tip contact's tangent against the stop, t(L) . nu at lambda (R_n by Brent's method):
  // <= 0 while only the tip touches; > 0 where the span behind the tip would cross the stop.
  double tip_slope(double lambda);
  double last_segment_start() const;

  void fill(double lambda, bool contact, double variable, ContactResult& out);
  // The stability verdict of the state at full load (ContactResult::stability).
  Stability verdict(bool contact, double variable);
  Stability point_verdict();

  const SegmentChain& full_;
  RigidSurface surface_;
  TipLoad start_;
  RigidContactSolver::Options options_;
  ShootingSolver::Options plain_options_;
  ShootingSolver::Options sampled_options_;
  double length_ = 1.0;
  // circle
  int sigma_ = 1;
  double radius_ = 1.0;
  double EI_ = 1.0;
  double L1_ = 1.0;
  bool wrap_ = false;  // a circle tangent at the clamp: the wrap model
  // line
  V2 point_ = V2::Zero();
  V2 normal_ = V2(0, 1);
  long solves_ = 0;
  // The free solution's smallest interior gap and where it is (set by indicator()).
  double free_tip_gap_ = 0.0;
  double free_interior_gap_ = 0.0;
  double free_interior_s_ = 0.0;
  // Point contact at an interior point: the contact point and its normal force.
  ContactMode mode_ = ContactMode::kNone;
  double point_s_ = 0.0;
  double point_P_ = 0.0;
  double point_phi_ = 0.0;
  // Line contact: the separation point a, the concentrated reaction R_a there, the stop's tangent
  // in the beam's running direction; the last tip reaction (warm start of tip_slope()).
  double lying_a_ = 0.0;
  double lying_R_ = 0.0;
  V2 tau_ = V2(1, 0);
  double tip_Rn_ = 0.0;
  double min_gap_s_ = 0.0;  // where min_gap() found the smallest gap
  // Several surfaces: this one's table number and the others.
  int self_id_ = 0;
  std::vector<RigidSurface> others_;
  std::vector<int> other_ids_;
  double other_gap_ = std::numeric_limits<double>::infinity();
  double other_s_ = 0.0;
  int other_index_ = -1;
};

// The gap of a point to a surface: the distance to the circle minus its radius, or the signed
// distance to the line along its (normalised) normal.
double surface_gap(const RigidSurface& surface, const V2& r) {
  if (surface.type == ContactSurfaceType::kCircle) {
    return (r - V2(surface.center[0], surface.center[1])).norm() - surface.radius;
  }
  const V2 n(surface.normal[0], surface.normal[1]);
  return n.dot(r - V2(surface.point[0], surface.point[1])) / n.norm();
}

void ContactRun::note_other_gaps(const std::vector<ShapePoint>& shape) {
  for (std::size_t j = 0; j < others_.size(); ++j) {
    for (const ShapePoint& p : shape) {
      const double g = surface_gap(others_[j], V2(p.x, p.y));
      if (g < other_gap_) {
        other_gap_ = g;
        other_s_ = p.s;
        other_index_ = static_cast<int>(j);
      }
    }
  }
}

std::string ContactRun::surface_name() const {
  if (self_id_ == 0) return to_string(surface_.type);
  return fmt::format("{} (contact {})", to_string(surface_.type), self_id_);
}

void ContactRun::validate() {
  full_.validate();
  if (full_.end != EndCondition::kFree) {
    throw InvalidInput(fmt::format(
        "contact with a rigid surface needs a free end (boundary 'free'); got '{}': contact with "
        "a prescribed end is not implemented",
        to_string(full_.end)));
  }
  for (double v : {start_.Fx, start_.Fy, start_.M, start_.follower}) {
    if (!std::isfinite(v)) throw InvalidInput("contact: the start tip load must be finite");
  }
  if (surface_.type == ContactSurfaceType::kCircle) {
    const double R = surface_.radius;
    if (!(R > 0.0) || !std::isfinite(R)) {
      throw InvalidInput(fmt::format("contact circle: radius must be positive (got {})", R));
    }
    const double cx = surface_.center[0], cy = surface_.center[1];
    if (!std::isfinite(cx) || !std::isfinite(cy)) {
      throw InvalidInput("contact circle: center must be finite");
    }
    // Tangent at the clamp (the centre on the clamp's normal at distance R): the wrap. Otherwise
    // the circle must be clear of the unloaded beam: point contact at an interior point.
    radius_ = R;
    wrap_ = std::abs(cx) <= 1e-9 * R && std::abs(std::abs(cy) - R) <= 1e-9 * R;
    if (!wrap_) {
      SegmentChain unloaded = full_.at_load_factor(0.0);
      unloaded.tip_load = TipLoad{};
      const ShootingResult r = ShootingSolver(sampled_options_).solve(unloaded);
      if (!r.converged() || gap_of(V2::Zero()) <= 0.0 ||
          min_gap(r.shape, false, false) <= options_.gap_tolerance * length_) {
        throw InvalidInput(fmt::format(
            "contact circle: center ({:g}, {:g}) with radius {:g} neither touches the beam "
            "tangent at the clamp (the wrap: centre (0, +R) or (0, -R)) nor stays clear of the "
            "unloaded beam (point contact); a circle that cuts or touches the unloaded beam "
            "elsewhere is not implemented",
            cx,
            cy,
            R));
      }
      return;
    }
    sigma_ = cy > 0.0 ? 1 : -1;
    radius_ = R;
    const auto* first = std::get_if<FlexibleSegment>(&full_.segments.front());
    if (first == nullptr) {
      throw InvalidInput(
          "contact circle: the first segment must be flexible (it wraps the circle)");
    }
    if (!first->EI_profile.empty() || first->kappa0 != 0.0) {
      throw InvalidInput(
          "contact circle: the wrapped first segment must be straight with a constant EI "
          "(EI_profile and kappa0 are not implemented with contact)");
    }
    if (full_.has_distributed_loads() || full_.has_extensible_segments()) {
      throw InvalidInput(
          "contact circle: distributed loads and extensible segments are not implemented with a "
          "circle (the wrap statics assume no load between the clamp and the separation point)");
    }
    EI_ = first->EI;
    L1_ = first->length;
  } else {
    const V2 n(surface_.normal[0], surface_.normal[1]);
    const V2 p(surface_.point[0], surface_.point[1]);
    if (!std::isfinite(n.x()) || !std::isfinite(n.y()) || !std::isfinite(p.x()) ||
        !std::isfinite(p.y())) {
      throw InvalidInput("contact line: point and normal must be finite");
    }
    if (!(n.norm() > 0.0)) throw InvalidInput("contact line: normal must not be zero");
    normal_ = n / n.norm();
    point_ = p;
    if (gap_of(V2::Zero()) <= 0.0) {
      throw InvalidInput(fmt::format(
          "contact line: the clamp lies on or behind the stop (gap {:g}); the normal must point "
          "from the stop toward the beam",
          gap_of(V2::Zero())));
    }
    // The unloaded chain must not cross the stop.
    ShootingSolver::Options o = sampled_options_;
    SegmentChain unloaded = full_.at_load_factor(0.0);
    unloaded.tip_load = TipLoad{};
    const ShootingResult r = ShootingSolver(o).solve(unloaded);
    if (r.converged() && min_gap(r.shape, false, false) < -options_.gap_tolerance * length_) {
      throw InvalidInput(
          "contact line: the unloaded beam already crosses the stop; move the stop or flip its "
          "normal");
    }
  }
}

SegmentChain ContactRun::chain_at(double lambda) const {
  SegmentChain c = full_.at_load_factor(lambda);
  const TipLoad& f = full_.tip_load;
  c.tip_load.Fx = start_.Fx + lambda * (f.Fx - start_.Fx);
  c.tip_load.Fy = start_.Fy + lambda * (f.Fy - start_.Fy);
  c.tip_load.M = start_.M + lambda * (f.M - start_.M);
  c.tip_load.follower = start_.follower + lambda * (f.follower - start_.follower);
  return c;
}

ShootingResult ContactRun::shoot(const SegmentChain& chain, bool sampled) {
  ++solves_;
  ShootingResult r = ShootingSolver(sampled ? sampled_options_ : plain_options_).solve(chain);
  if (!r.converged()) {
    throw ContactFailure(fmt::format("a shooting solve did not converge: {}", r.message));
  }
  return r;
}

double ContactRun::gap_of(const V2& r) const {
  if (surface_.type == ContactSurfaceType::kCircle) {
    const V2 c(surface_.center[0], surface_.center[1]);
    return (r - c).norm() - surface_.radius;
  }
  return normal_.dot(r - point_);
}

double ContactRun::min_gap(const std::vector<ShapePoint>& shape, bool skip_last, bool skip_root) {
  double g = std::numeric_limits<double>::infinity();
  const std::size_t n = shape.size();
  for (std::size_t i = skip_root ? 1 : 0; i + (skip_last ? 1 : 0) < n; ++i) {
    const double gi = gap_of(V2(shape[i].x, shape[i].y));
    if (gi < g) {
      g = gi;
      min_gap_s_ = shape[i].s;
    }
  }
  return g;
}

std::string ContactRun::contact_description(double variable) const {
  switch (mode_) {
    case ContactMode::kWrap:
      return fmt::format("wrapping the {} over s = 0 .. {:.6g}", surface_name(), variable);
    case ContactMode::kTip:
      return fmt::format("touching the {} with its tip (s = {:.6g})", surface_name(), length_);
    case ContactMode::kPoint:
      return fmt::format("touching the {} at s = {:.6g}", surface_name(), point_s_);
    case ContactMode::kLying:
      return fmt::format(
          "lying on the {} over s = {:.6g} .. {:.6g}", surface_name(), lying_a_, length_);
    default:
      return fmt::format("free of the {}", surface_name());
  }
}

double ContactRun::indicator(double lambda, double* interior_gap) {
  const SegmentChain c = chain_at(lambda);
  if (wrap_) {
    const ShootingResult r = shoot(c, interior_gap != nullptr);
    const double m0 = -r.reaction.M;
    if (interior_gap) *interior_gap = min_gap(r.shape, false, true);
    return EI_ / radius_ - sigma_ * m0;
  }
  // The smallest gap of the free beam: at the tip, or at an interior sample refined by the
  // parabola through it and its neighbours (the gap is smooth in s; error O(h^4)).
  const ShootingResult r = shoot(c, true);
  const std::size_t n = r.shape.size();
  std::vector<double> g(n);
  for (std::size_t i = 0; i < n; ++i) g[i] = gap_of(V2(r.shape[i].x, r.shape[i].y));
  std::size_t k = 1;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (g[i] < g[k]) k = i;
  }
  double gi = g[k], si = r.shape[k].s;
  if (k >= 1 && k + 1 < n) {
    const double curvature = g[k - 1] - 2.0 * g[k] + g[k + 1];
    if (curvature > 0.0) {
      const double delta = 0.5 * (g[k - 1] - g[k + 1]) / curvature;
      if (std::abs(delta) <= 1.0) {
        gi = g[k] - 0.25 * (g[k - 1] - g[k + 1]) * delta;
        si = r.shape[k].s + delta * (r.shape[k + 1].s - r.shape[k].s);
      }
    }
  }
  free_tip_gap_ = gap_of(V2(r.tip.x, r.tip.y));
  free_interior_gap_ = gi;
  free_interior_s_ = si;
  if (interior_gap) *interior_gap = gi;
  return std::min(free_tip_gap_, gi);
}

V2 ContactRun::gap_gradient(const V2& r) const {
  if (surface_.type == ContactSurfaceType::kLine) return normal_;
  const V2 d = r - V2(surface_.center[0], surface_.center[1]);
  return d / d.norm();
}

SegmentChain ContactRun::split_chain(const SegmentChain& chain, double s, const V2& force) const {
  SegmentChain out = chain;
  double start = 0.0;
  for (int j = 0; j < chain.segment_count(); ++j) {
    const Segment& seg = chain.segments[j];
    const double len = std::visit([](const auto& x) { return x.length; }, seg);
    if (s < start + len || j + 1 == chain.segment_count()) {
      const auto* f = std::get_if<FlexibleSegment>(&seg);
      if (f == nullptr) throw ContactFailure("contact on a rigid link is not implemented");
      if (!f->EI_profile.empty() || !f->q_profile.empty()) {
        throw ContactFailure(
            "point contact on a segment with a tabulated EI or load is not implemented");
      }
      const double a = s - start, b = start + len - s;
      if (a < 1e-9 * length_ || b < 1e-9 * length_) {
        throw ContactFailure("point contact at a joint of the chain is not implemented");
      }
      FlexibleSegment near = *f, far = *f;
      near.length = a;
      far.length = b;
      out.segments[j] = near;
      out.segments.insert(out.segments.begin() + j + 1, far);
      for (NodeLoad& load : out.node_loads) {
        if (load.node >= j + 1) ++load.node;
      }
      out.node_loads.push_back(NodeLoad{j + 1, force.x(), force.y(), 0.0});
      return out;
    }
    start += len;
  }
  throw ContactFailure("the contact point lies outside the chain");
}

Eigen::Vector3d ContactRun::point_residual(const SegmentChain& chain,
                                           const Eigen::Vector3d& z,
                                           ChainPose* pose) {
  // z = (s, P, phi): contact point, normal force and its direction angle. Residuals: the gap at
  // the point (in lengths), the tangency t . grad g, and the direction against grad g there.
  const double s = z[0], P = z[1], phi = z[2];
  const V2 direction(std::cos(phi), std::sin(phi));
  const SegmentChain split = split_chain(chain, s, P * direction);
  const ShootingResult r = shoot(split, false);
  const std::vector<ShapePoint> at = shooting_shape_at(split, r, {s}, plain_options_);
  const V2 rp(at[0].x, at[0].y);
  const V2 t(std::cos(at[0].theta), std::sin(at[0].theta));
  const V2 grad = gap_gradient(rp);
  if (pose) *pose = ChainPose{at[0].x, at[0].y, at[0].theta};
  return Eigen::Vector3d(
      gap_of(rp) / length_, t.dot(grad), direction.x() * grad.y() - direction.y() * grad.x());
}

double ContactRun::most_flexible_force_scale() const {
  double EI_min = std::numeric_limits<double>::infinity();
  for (const Segment& seg : full_.segments) {
    if (const auto* f = std::get_if<FlexibleSegment>(&seg)) EI_min = std::min(EI_min, f->EI);
  }
  return EI_min / (length_ * length_);
}

void ContactRun::solve_point(const SegmentChain& chain) {
  // Newton's method on (s, P, phi) with a forward-difference Jacobian (each column a shooting
  // solve) and backtracking on |g|; from the previous contact state (or the landing point).
  const double force_scale = most_flexible_force_scale();
  Eigen::Vector3d z(point_s_, point_P_, point_phi_);
  Eigen::Vector3d g;
  const bool converged = damped_newton<3>(
      [&](const Eigen::Vector3d& zz) { return point_residual(chain, zz, nullptr); },
      [&](const Eigen::Vector3d& zz) {
        return Eigen::Vector3d(1e-7 * length_, 1e-7 * std::max(std::abs(zz[1]), force_scale), 1e-7);
      },
      [&](Eigen::Vector3d& trial) {
        trial[0] = std::clamp(trial[0], 1e-6 * length_, length_ * (1.0 - 1e-6));
      },
      Eigen::Vector3d(1e-13, 1e-12, 1e-12),
      "the point contact's Newton step is singular",
      z,
      g);
  if (converged) {
    point_s_ = z[0];
    point_P_ = z[1];
    point_phi_ = z[2];
    return;
  }
  throw ContactFailure(
      fmt::format("the interior point contact did not converge (residual {:.3g})", g.norm()));
}

ContactMode ContactRun::landing_mode(double lambda) {
  if (wrap_) return ContactMode::kWrap;
  indicator(lambda);
  if (free_tip_gap_ <= free_interior_gap_) {
    if (surface_.type == ContactSurfaceType::kCircle) {
      throw ContactFailure(
          "the tip lands on the circle: tip contact with a circle is not implemented");
    }
    return ContactMode::kTip;
  }
  // Start Newton at the free beam's closest point with no force, along the surface normal there.
  const SegmentChain c = chain_at(lambda);
  const ShootingResult r = shoot(c, false);
  const std::vector<ShapePoint> at = shooting_shape_at(c, r, {free_interior_s_}, plain_options_);
  const V2 grad = gap_gradient(V2(at[0].x, at[0].y));
  point_s_ = free_interior_s_;
  point_P_ = 0.0;
  point_phi_ = std::atan2(grad.y(), grad.x());
  return ContactMode::kPoint;
}

double ContactRun::last_segment_start() const {
  const Segment& last = full_.segments.back();
  return length_ - std::visit([](const auto& x) { return x.length; }, last);
}

void ContactRun::check_lying(const SegmentChain& chain) const {
  const auto* f = std::get_if<FlexibleSegment>(&chain.segments.back());
  auto refuse = [](const char* why) {
    throw ContactFailure(fmt::format(
        "the tip contact opens into a line contact (the beam lying on the stop), which is "
        "implemented for a last segment that is flexible, straight, inextensible and of constant "
        "EI and load, with no tip moment: {}",
        why));
  };
  if (f == nullptr) refuse("the last segment is a rigid link");
  if (!f->EI_profile.empty() || !f->q_profile.empty()) refuse("it has an EI_profile or q_profile");
  if (f->kappa0 != 0.0) refuse("it has a stress-free curvature kappa0");
  if (f->extensible() || f->shear_flexible()) refuse("it is extensible or shear-flexible");
  if (chain.tip_load.M != 0.0) refuse("a tip moment acts on the lying part");
}

ContactRun::LyingStatics ContactRun::lying_statics(const SegmentChain& chain, double a) const {
  // The lying part (a, L] is straight along tau with m = 0, so m' = 0 makes its internal force
  // axial, N = N_t tau; the stop balances every normal load where it acts (frictionless):
  //   p = -(q + q_f n) . nu on the part,  R_L = -F_tip . nu at the tip,
  // and N_t(a+) = (F_tip + integral of q over (a, L]) . tau (the follower pressure is normal).
  const auto& f = std::get<FlexibleSegment>(chain.segments.back());
  const double s0 = length_ - f.length;
  const V2 n_tau(-tau_.y(), tau_.x());  // the beam's left normal on the stop
  const V2 F_tip = V2(chain.tip_load.Fx, chain.tip_load.Fy) + chain.tip_load.follower * n_tau;
  const std::array<double, 2> Qe = f.q_resultant(f.length), Qa = f.q_resultant(a - s0);
  const V2 Q(Qe[0] - Qa[0], Qe[1] - Qa[1]);
  const std::array<double, 2> q = f.q_at(a - s0);
  LyingStatics out;
  out.N_t = (F_tip + Q).dot(tau_);
  out.tip_reaction = -F_tip.dot(normal_);
  out.pressure = -(V2(q[0], q[1]) + f.q_follower * n_tau).dot(normal_);
  return out;
}

SegmentChain ContactRun::lying_span(const SegmentChain& chain, double a, double R) const {
  const double s0 = last_segment_start();
  if (a - s0 <= 1e-9 * length_) {
    throw ContactFailure(
        "the line contact reaches back to the start of the last segment (a line contact over "
        "several segments is not implemented)");
  }
  const LyingStatics st = lying_statics(chain, a);
  SegmentChain span = chain;
  std::get<FlexibleSegment>(span.segments.back()).length = a - s0;
  const V2 end = st.N_t * tau_ + R * normal_;
  span.tip_load = TipLoad{end.x(), end.y(), 0.0, 0.0};
  return span;
}

Eigen::Vector2d ContactRun::lying_residual(const SegmentChain& chain, double a, double R) {
  const ShootingResult r = shoot(lying_span(chain, a, R), false);
  const V2 t(std::cos(r.tip.theta), std::sin(r.tip.theta));
  return Eigen::Vector2d(gap_of(V2(r.tip.x, r.tip.y)) / length_, t.dot(normal_));
}

void ContactRun::solve_lying(const SegmentChain& chain) {
  // Newton's method on (a, R_a) with a backward-difference Jacobian (a <= L) and backtracking,
  // from the previous state (or a = L and the tip reaction where the tip contact opened).
  check_lying(chain);
  const double force_scale = most_flexible_force_scale();
  Eigen::Vector2d z(std::min(lying_a_, length_), lying_R_);
  Eigen::Vector2d g;
  // Backward differences in a: the span cannot be longer than the beam (a <= L).
  const bool converged = damped_newton<2>(
      [&](const Eigen::Vector2d& zz) { return lying_residual(chain, zz[0], zz[1]); },
      [&](const Eigen::Vector2d& zz) {
        return Eigen::Vector2d(-1e-7 * length_, 1e-7 * std::max(std::abs(zz[1]), force_scale));
      },
      [&](Eigen::Vector2d& trial) { trial[0] = std::min(trial[0], length_); },
      Eigen::Vector2d(1e-13, 1e-12),
      "the line contact's Newton step is singular",
      z,
      g);
  if (converged) {
    const ShootingResult r = shoot(lying_span(chain, z[0], z[1]), false);
    if (std::cos(r.tip.theta) * tau_.x() + std::sin(r.tip.theta) * tau_.y() <= 0.0) {
      throw ContactFailure("the line contact converged to a span turned against the stop");
    }
    lying_a_ = z[0];
    lying_R_ = z[1];
    return;
  }
  throw ContactFailure(
      fmt::format("the line contact (the beam lying on the stop) did not converge (residual "
                  "{:.3g}; separation point s = {:.6g})",
                  g.norm(),
                  z[0]));
}

double ContactRun::tip_slope(double lambda) {
  const SegmentChain c = chain_at(lambda);
  tip_Rn_ = solve_tip_reaction(c, tip_Rn_);
  const ShootingResult r = shoot(with_reaction(c, tip_Rn_), false);
  return std::cos(r.tip.theta) * normal_.x() + std::sin(r.tip.theta) * normal_.y();
}

ChainPose ContactRun::wrap_pose(double s) const {
  const double phi = s / radius_;
  return ChainPose{radius_ * std::sin(phi), sigma_ * radius_ * (1.0 - std::cos(phi)), sigma_ * phi};
}

SegmentChain ContactRun::span_chain(const SegmentChain& chain, double s_c) const {
  // The free span in the frame of its root (the circle's pose at s_c): dead forces rotated by
  // -theta_c, moments and the follower force unchanged.
  const double theta_c = wrap_pose(s_c).theta;
  SegmentChain span = chain;
  std::get<FlexibleSegment>(span.segments.front()).length = L1_ - s_c;
  rotate_dead_forces(span, -theta_c);
  return span;
}

double ContactRun::curvature_residual(const SegmentChain& chain, double s_c) {
  const ShootingResult r = shoot(span_chain(chain, s_c), false);
  return sigma_ * (-r.reaction.M) - EI_ / radius_;
}

double ContactRun::solve_wrap(const SegmentChain& chain, double guess) {
  // f(0) > 0 where contact holds; f decreases as the free span shortens. Bracket from the last
  // point known positive toward the end of the first segment.
  double a = 0.0;
  double fa = curvature_residual(chain, 0.0);
  if (fa <= 0.0) return 0.0;
  if (guess > 0.0 && guess < L1_) {
    const double fg = curvature_residual(chain, guess);
    if (fg > 0.0) {
      a = guess;
      fa = fg;
    } else {
      const ScalarRootResult root =
          brent_root([&](double s) { return curvature_residual(chain, s); },
                     0.0,
                     guess,
                     fa,
                     fg,
                     ScalarRootOptions{options_.contact_tolerance * L1_, 200});
      if (!root.converged()) throw ContactFailure("the separation point did not converge");
      return root.x;
    }
  }
  for (int k = 1; k <= 80; ++k) {
    const double b = a + 0.25 * (L1_ - a);
    double fb = 0.0;
    try {
      fb = curvature_residual(chain, b);
    } catch (const ContactFailure&) {
      fb = std::numeric_limits<double>::quiet_NaN();
    }
    if (std::isfinite(fb) && fb <= 0.0) {
      const ScalarRootResult root =
          brent_root([&](double s) { return curvature_residual(chain, s); },
                     a,
                     b,
                     fa,
                     fb,
                     ScalarRootOptions{options_.contact_tolerance * L1_, 200});
      if (!root.converged()) throw ContactFailure("the separation point did not converge");
      return root.x;
    }
    if (!std::isfinite(fb) || L1_ - b < 1e-9 * L1_) break;
    a = b;
    fa = fb;
  }
  throw ContactFailure(
      "no separation point on the first segment: the free span stays curved tighter than the "
      "circle up to the end of the segment (a segment wrapped whole is not implemented)");
}

SegmentChain ContactRun::with_reaction(const SegmentChain& chain, double Rn) const {
  SegmentChain c = chain;
  c.tip_load.Fx += Rn * normal_.x();
  c.tip_load.Fy += Rn * normal_.y();
  return c;
}

double ContactRun::tip_gap(const SegmentChain& chain, double Rn) {
  const ShootingResult r = shoot(with_reaction(chain, Rn), false);
  return gap_of(V2(r.tip.x, r.tip.y));
}

double ContactRun::solve_tip_reaction(const SegmentChain& chain, double guess) {
  double a = 0.0;
  double ga = tip_gap(chain, 0.0);
  if (ga >= 0.0) return 0.0;
  // A scale of the reaction: the force that moves the tip by a length's tenth, EI/L^2.
  double EI_min = std::numeric_limits<double>::infinity();
  for (const Segment& s : full_.segments) {
    if (const auto* f = std::get_if<FlexibleSegment>(&s)) {
      EI_min = std::min(EI_min,
                        f->EI_profile.empty()
                            ? f->EI
                            : *std::min_element(f->EI_profile.begin(), f->EI_profile.end()));
    }
  }
  double b = guess > 0.0 ? 1.25 * guess : 0.1 * EI_min / (length_ * length_);
  for (int k = 0; k < 200; ++k) {
    const double gb = tip_gap(chain, b);
    if (gb >= 0.0) {
      const ScalarRootResult root =
          brent_root([&](double Rn) { return tip_gap(chain, Rn); },
                     a,
                     b,
                     ga,
                     gb,
                     ScalarRootOptions{options_.contact_tolerance * b, 200});
      if (!root.converged()) throw ContactFailure("the tip reaction did not converge");
      return root.x;
    }
    a = b;
    ga = gb;
    b *= 2.0;
  }
  throw ContactFailure("no tip reaction brings the tip back to the stop");
}

void ContactRun::fill(double lambda, bool contact, double variable, ContactResult& out) {
  const SegmentChain chain = chain_at(lambda);
  out.load_factor = lambda;
  out.in_contact = contact;
  out.tip_load = Reaction{chain.tip_load.Fx, chain.tip_load.Fy, chain.tip_load.M};
  out.separation_s.clear();
  out.separation_points.clear();
  out.shape.clear();
  out.s_start = out.s_end = 0.0;
  out.contact_force = out.point_force = {0.0, 0.0};
  out.point_force_normal = out.line_pressure = out.wrap_tension = 0.0;
  out.tip_reaction_normal = out.lying_axial_force = 0.0;
  other_gap_ = std::numeric_limits<double>::infinity();
  other_index_ = -1;
  out.separation_moment = out.curvature_condition = 0.0;
  const int n_shape = options_.shape_points;
  if (contact && mode_ == ContactMode::kPoint) {
    const V2 direction(std::cos(point_phi_), std::sin(point_phi_));
    const SegmentChain split = split_chain(chain, point_s_, point_P_ * direction);
    const ShootingResult r = shoot(split, true);
    const std::vector<ShapePoint> at = shooting_shape_at(split, r, {point_s_}, plain_options_);
    const ChainPose pose{at[0].x, at[0].y, at[0].theta};
    out.tip = r.tip;
    out.reaction = r.reaction;
    out.min_gap = min_gap(r.shape, false, false);
    note_other_gaps(r.shape);
    out.tip_gap = gap_of(V2(r.tip.x, r.tip.y));
    out.residual = std::abs(gap_of(V2(pose.x, pose.y)));
    out.s_start = out.s_end = point_s_;
    out.separation_s = {point_s_};
    out.separation_points = {pose};
    out.point_force = {point_P_ * direction.x(), point_P_ * direction.y()};
    out.point_force_normal = point_P_;
    out.contact_force = out.point_force;
    if (n_shape > 1) {
      ShootingSolver::Options os = plain_options_;
      os.shape_points = n_shape;
      out.shape = ShootingSolver(os).solve(split).shape;
    }
    return;
  }
  if (contact && mode_ == ContactMode::kLying) {
    const double a = lying_a_, R = lying_R_;
    const SegmentChain span = lying_span(chain, a, R);
    const ShootingResult r = shoot(span, true);
    const LyingStatics st = lying_statics(chain, a);
    const ChainPose pa = r.tip;  // the separation point: the free span's end
    const V2 tip = V2(pa.x, pa.y) + (length_ - a) * tau_;
    out.tip = ChainPose{tip.x(), tip.y(), pa.theta};
    out.reaction = r.reaction;  // the lying part's loads reach the clamp through the span
    out.min_gap = min_gap(r.shape, true, false);
    note_other_gaps(r.shape);
    if (!others_.empty()) {
      std::vector<ShapePoint> lying;
      for (int i = 1; i <= 50; ++i) {
        const double ds = (length_ - a) * i / 50.0;
        const V2 p = V2(pa.x, pa.y) + ds * tau_;
        lying.push_back(ShapePoint{a + ds, p.x(), p.y(), pa.theta});
      }
      note_other_gaps(lying);
    }
    out.tip_gap = gap_of(tip);
    out.residual = std::abs(gap_of(V2(pa.x, pa.y)));
    out.s_start = a;
    out.s_end = length_;
    out.separation_s = {a};
    out.separation_points = {pa};
    out.point_force = {R * normal_.x(), R * normal_.y()};
    out.point_force_normal = R;
    out.line_pressure = st.pressure;
    out.tip_reaction_normal = st.tip_reaction;
    out.lying_axial_force = st.N_t;
    const double total = R + st.pressure * (length_ - a) + st.tip_reaction;
    out.contact_force = {total * normal_.x(), total * normal_.y()};
    const double tol = 1e-9 * std::max({std::abs(R), std::abs(st.N_t), 1e-300});
    if (R < -tol || st.tip_reaction < -tol ||
        st.pressure < -1e-9 * std::max(std::abs(st.pressure), 1e-300)) {
      throw ContactFailure(fmt::format(
          "the line contact would need a stop that pulls (reaction at the separation point {:g}, "
          "line pressure {:g}, tip reaction {:g}): a beam that lifts off the stop behind its tip "
          "is not implemented",
          R,
          st.pressure,
          st.tip_reaction));
    }
    if (n_shape > 1) {
      const int lying_points = std::clamp(
          static_cast<int>(std::lround(n_shape * (length_ - a) / length_)), 1, n_shape - 2);
      ShootingSolver::Options os = plain_options_;
      os.shape_points = n_shape - lying_points;
      out.shape = ShootingSolver(os).solve(span).shape;
      for (int i = 1; i <= lying_points; ++i) {
        const double ds = (length_ - a) * i / lying_points;
        const V2 p = V2(pa.x, pa.y) + ds * tau_;
        out.shape.push_back(ShapePoint{a + ds, p.x(), p.y(), pa.theta});
      }
    }
    return;
  }
  if (surface_.type == ContactSurfaceType::kCircle) {
    if (!contact) {
      ShootingSolver::Options o = sampled_options_;
      const ShootingResult r = ShootingSolver(o).solve(chain);
      ++solves_;
      if (!r.converged()) throw ContactFailure("the free beam did not converge: " + r.message);
      out.tip = r.tip;
      out.reaction = r.reaction;
      out.min_gap = min_gap(r.shape, false, true);
      note_other_gaps(r.shape);
      out.tip_gap = gap_of(V2(r.tip.x, r.tip.y));
      out.residual = 0.0;
      if (n_shape > 1) {
        ShootingSolver::Options os = plain_options_;
        os.shape_points = n_shape;
        out.shape = ShootingSolver(os).solve(chain).shape;
      }
      return;
    }
    const double s_c = variable;
    const ChainPose pc = wrap_pose(s_c);
    const SegmentChain span = span_chain(chain, s_c);
    const ShootingResult r = shoot(span, true);
    const V2 rc(pc.x, pc.y);
    auto to_root = [&](const ShapePoint& p, double s0) {
      const V2 g = rc + rotate(pc.theta, V2(p.x, p.y));
      return ShapePoint{s0 + p.s, g.x(), g.y(), pc.theta + p.theta};
    };
    // Tip and the free span's gaps, root frame.
    std::vector<ShapePoint> span_shape;
    for (const ShapePoint& p : r.shape) span_shape.push_back(to_root(p, s_c));
    const ShapePoint tip = to_root(ShapePoint{length_ - s_c, r.tip.x, r.tip.y, r.tip.theta}, 0.0);
    out.tip = ChainPose{tip.x, tip.y, tip.theta};
    out.min_gap = min_gap(span_shape, false, true);
    note_other_gaps(span_shape);
    if (!others_.empty()) {
      std::vector<ShapePoint> wrap;
      for (int i = 0; i <= 50; ++i) {
        const ChainPose p = wrap_pose(s_c * i / 50.0);
        wrap.push_back(ShapePoint{s_c * i / 50.0, p.x, p.y, p.theta});
      }
      note_other_gaps(wrap);
    }
    out.tip_gap = gap_of(V2(tip.x, tip.y));
    // Statics of the wrap (rigid_contact.h): N(s_c+) from the free span, rotated back.
    const V2 N = rotate(pc.theta, V2(-r.reaction.Fx, -r.reaction.Fy));
    const V2 t(std::cos(pc.theta), std::sin(pc.theta));
    const V2 nrm(-std::sin(pc.theta), std::cos(pc.theta));
    const double T = N.dot(t);
    const double Pc = sigma_ * N.dot(nrm);
    const V2 e_c = -sigma_ * nrm;  // the circle's outward normal at s_c
    const double phi = s_c / radius_;
    const V2 pressure_resultant = T * V2(1.0 - std::cos(phi), -sigma_ * std::sin(phi));
    const V2 total = Pc * e_c + pressure_resultant;
    out.s_start = 0.0;
    out.s_end = s_c;
    out.separation_s = {s_c};
    out.separation_points = {pc};
    out.point_force = {Pc * e_c.x(), Pc * e_c.y()};
    out.point_force_normal = Pc;
    out.line_pressure = T / radius_;
    out.wrap_tension = T;
    out.contact_force = {total.x(), total.y()};
    out.separation_moment = -r.reaction.M;
    out.curvature_condition = out.separation_moment - sigma_ * EI_ / radius_;
    out.residual = std::abs(out.curvature_condition);
    // The wrap carries N = T t, m = sigma EI/R to the clamp (t(0) = +x).
    out.reaction = Reaction{-T, 0.0, -sigma_ * EI_ / radius_};
    if (T < -1e-9 * std::abs(N.norm()) || Pc < -1e-9 * std::abs(N.norm())) {
      throw ContactFailure(fmt::format(
          "the wrap would need a circle that pulls (line pressure T/R = {:g}, point force {:g}): "
          "with the wrap compressed the beam lifts off between the clamp and an interior contact "
          "point, which is not implemented",
          T / radius_,
          Pc));
    }
    if (n_shape > 1) {
      const int wrap_points =
          std::clamp(static_cast<int>(std::lround(n_shape * s_c / length_)), 1, n_shape - 2);
      for (int i = 0; i < wrap_points; ++i) {
        const double s = s_c * i / wrap_points;
        const ChainPose p = wrap_pose(s);
        out.shape.push_back(ShapePoint{s, p.x, p.y, p.theta});
      }
      ShootingSolver::Options os = plain_options_;
      os.shape_points = n_shape - wrap_points;
      const ShootingResult rs = ShootingSolver(os).solve(span);
      for (const ShapePoint& p : rs.shape) out.shape.push_back(to_root(p, s_c));
    }
    return;
  }
  // Line.
  const double Rn = contact ? variable : 0.0;
  const SegmentChain loaded = with_reaction(chain, Rn);
  const ShootingResult r = shoot(loaded, true);
  out.tip = r.tip;
  out.reaction = r.reaction;
  out.min_gap = min_gap(r.shape, contact, false);
  note_other_gaps(r.shape);
  out.tip_gap = gap_of(V2(r.tip.x, r.tip.y));
  out.residual = contact ? std::abs(out.tip_gap) : 0.0;
  if (contact) {
    out.s_start = out.s_end = length_;
    out.separation_s = {length_};
    out.separation_points = {r.tip};
    out.point_force = {Rn * normal_.x(), Rn * normal_.y()};
    out.point_force_normal = Rn;
    out.contact_force = out.point_force;
  }
  if (n_shape > 1) {
    ShootingSolver::Options os = plain_options_;
    os.shape_points = n_shape;
    out.shape = ShootingSolver(os).solve(loaded).shape;
  }
}

// The verdict (docs/contact.md, "Stability"). Frictionless contact with a positive contact force
// restricts the admissible variations to those that keep the contact (a variation that lifts
// the beam off against a positive pressure raises the energy at first order, so only the
// variations tangent to the surface there are left to the second variation): the wrap's pressure
// T/R and point force P_c are positive (fill() refuses them negative), so the wrap stays on the
// circle and the free span is a cantilever clamped at s_c with its own loads; the tip on a stop
// keeps its normal coordinate, a constraint normal . delta r(L) = 0 with the reaction R_n as its
// multiplier (held_stability.h, in a frame turned so that the normal is +y).
Stability ContactRun::verdict(bool contact, double variable) {
  const SegmentChain chain = chain_at(1.0);
  const StabilityOptions& so = options_.stability;
  auto shape_of = [&](const SegmentChain& c, const ShootingResult& r) {
    return ShapeAtStations([&c, r, this](const std::vector<double>& s) {
      return shooting_shape_at(c, r, s, plain_options_);
    });
  };
  if (!contact) {
    const ShootingResult r = shoot(chain, false);
    return equilibrium_stability(chain, Reaction{}, shape_of(chain, r), so);
  }
  switch (mode_) {
    case ContactMode::kWrap: {
      const SegmentChain span = span_chain(chain, variable);
      const ShootingResult r = shoot(span, false);
      Stability v = equilibrium_stability(span, Reaction{}, shape_of(span, r), so);
      if (v.judged()) {
        v.message = fmt::format(
            "{} (the free span, clamped at the separation point s = {:.9g}: the wrap is pressed "
            "onto the circle)",
            v.message,
            variable);
      }
      return v;
    }
    case ContactMode::kTip: {
      const SegmentChain loaded = with_reaction(chain, variable);
      const ShootingResult r = shoot(loaded, false);
      // The frame turned by -psi, the stop's normal along +y there: a zero-length rigid kink at
      // the root turns the clamp, the loads turn with it (node k becomes k + 1).
      const double psi = std::atan2(normal_.y(), normal_.x()) - 0.5 * std::acos(-1.0);
      SegmentChain turned = chain;
      turned.segments.insert(turned.segments.begin(), RigidSegment{0.0, -psi});
      rotate_dead_forces(turned, -psi);
      for (NodeLoad& load : turned.node_loads) ++load.node;
      const ShapeAtStations shape = [&](const std::vector<double>& s) {
        std::vector<ShapePoint> out = shooting_shape_at(loaded, r, s, plain_options_);
        for (ShapePoint& p : out) {
          const V2 q = rotate(-psi, V2(p.x, p.y));
          p = ShapePoint{p.s, q.x(), q.y(), p.theta - psi};
        }
        return out;
      };
      PrescribedMask held;
      held.y = true;
      Stability v =
          equilibrium_stability_held(turned, Reaction{0.0, variable, 0.0}, shape, held, so);
      if (v.judged()) {
        v.message =
            fmt::format("{} (the tip held on the stop along its normal by the reaction {:.6g})",
                        v.message,
                        variable);
      }
      return v;
    }
    case ContactMode::kLying:
      return not_checked_stability(
          "the verdict of a line contact (the beam lying on the stop) is not implemented (the "
          "separation point moves with the variation)");
    case ContactMode::kPoint:
      return point_verdict();
    default:
      return not_checked_stability("no contact mode");
  }
}

// The verdict of an interior point contact with a stop (docs/contact.md, "Stability"). With the
// contact force P > 0 the admissible variations keep the gap's minimum, c = min_s g(r(s)) >= 0,
// so to first order nu . delta r(s_p) = int_0^s_p (nu . n) eta ds = 0 (the contact point's
// normal coordinate held). The Lagrangian Pi - P c differs from the energy of the chain with P a
// dead load at s_p by -P [c - g(r(s_p))], whose second variation is + P (d g_s)^2 / g_ss: the
// contact point rolls to where the varied beam is lowest, and with d g_s = (nu . n) eta(s_p),
// g_ss = kappa(s_p) (nu . n), the second variation gains the point term
//     P eta(s_p)^2 / |kappa(s_p)|      (kappa = theta' on the beam's side of the stop).
// Assembled on the chain cut at s_p (the discrete second variation of segment_chain.h,
// every 1st, 2nd and 4th sample, Romberg-extrapolated like the chain's own verdict) with the
// constraint row and the point term added at the dof of the cut.
Stability ContactRun::point_verdict() {
  if (surface_.type == ContactSurfaceType::kCircle) {
    return not_checked_stability(
        "the verdict of an interior point contact with a circle is not implemented (the pin's "
        "curvature adds -P (tau . delta r)^2 / R to the second variation, a term of the whole "
        "span's displacement; a stop's is implemented)");
  }
  const SegmentChain chain = chain_at(1.0);
  const V2 direction(std::cos(point_phi_), std::sin(point_phi_));
  const SegmentChain split = split_chain(chain, point_s_, point_P_ * direction);
  if (split.tip_load.follower != 0.0 || split.has_follower_pressure()) {
    return not_conservative_stability("a follower load acts on the beam");
  }
  for (const Segment& seg : split.segments) {
    const auto* f = std::get_if<FlexibleSegment>(&seg);
    if (f == nullptr || f->extensible() || f->shear_flexible()) {
      return not_checked_stability(
          "the verdict of an interior point contact is implemented for chains of inextensible "
          "flexible segments");
    }
  }
  const ShootingResult r = shoot(split, false);
  // Curvature on the near side of the contact point (one-sided, O(delta^2)).
  const double delta = 1e-4 * point_s_;
  const std::vector<ShapePoint> near = shooting_shape_at(
      split, r, {point_s_ - 2.0 * delta, point_s_ - delta, point_s_}, plain_options_);
  const double kappa = (3.0 * near[2].theta - 4.0 * near[1].theta + near[0].theta) / (2.0 * delta);
  const double nu_n =
      -normal_.x() * std::sin(near[2].theta) + normal_.y() * std::cos(near[2].theta);
  const double g_ss = kappa * nu_n;
  if (!(g_ss > 1e-9 / length_)) {
    return not_checked_stability(fmt::format(
        "the beam is as straight as the stop at the contact point (curvature {:.3g}): the point "
        "contact is opening into a line contact",
        kappa));
  }
  const double rolling = point_P_ / g_ss;
  // Stations: each segment in a multiple of 4 equal elements (grids of every 1st, 2nd, 4th).
  std::vector<int> elements;
  std::vector<double> s = {0.0};
  double start = 0.0;
  for (const Segment& seg : split.segments) {
    const double len = std::get<FlexibleSegment>(seg).length;
    const int n = 4 * std::max(4, static_cast<int>(std::ceil(100.0 * len / length_)));
    elements.push_back(n);
    for (int i = 1; i <= n; ++i) s.push_back(start + len * i / n);
    start += len;
  }
  const std::vector<ShapePoint> shape = shooting_shape_at(split, r, s, plain_options_);
  const StabilityOptions& so = options_.stability;
  std::array<double, 3> values{1.0, 1.0, 1.0};
  std::array<bool, 3> found{false, false, false};
  int index = 0;
  for (int level = 0; level < 3; ++level) {
    const int stride = 1 << level;
    DiscreteSecondVariation q = discrete_second_variation(split, Reaction{}, shape, stride);
    int total = 0;
    for (int n : elements) total += n / stride;
    if (q.size() != total || !q.constraints.empty()) {
      return not_checked_stability("the second variation of the cut chain has an unexpected form");
    }
    // The row int_0^s_p (nu . n) eta ds on the chords of the first segment's elements
    // (trapezoid, as the chain's own tip rows), and the rolling term at the cut's dof.
    std::vector<double> row(static_cast<std::size_t>(total), 0.0);
    const int n0 = elements[0] / stride;
    for (int e = 0; e < n0; ++e) {
      const ShapePoint& a = shape[static_cast<std::size_t>(e * stride)];
      const ShapePoint& b = shape[static_cast<std::size_t>((e + 1) * stride)];
      const double h = b.s - a.s;
      const double dx = b.x - a.x, dy = b.y - a.y, chord = std::hypot(dx, dy);
      const double v = (-normal_.x() * dy + normal_.y() * dx) / chord;
      if (e > 0) row[static_cast<std::size_t>(e - 1)] += 0.5 * h * v;
      row[static_cast<std::size_t>(e)] += 0.5 * h * v;
    }
    q.constraints.push_back(row);
    q.axial[static_cast<std::size_t>(n0 - 1)] += rolling;
    if (level == 0) index = constrained_count(q, -so.critical_tolerance);
    const PencilEigenvalue e = constrained_eigenvalue(q, 1, so.eigenvalue_tolerance);
    found[level] = e.exists;
    values[level] = e.value;
  }
  double lowest = 1.0;
  if (found[0] && found[1] && found[2]) {
    const double r_fine = (4.0 * values[0] - values[1]) / 3.0;
    const double r_coarse = (4.0 * values[1] - values[2]) / 3.0;
    lowest = std::min(1.0, (16.0 * r_fine - r_coarse) / 15.0);
  } else if (found[0]) {
    lowest = std::min(1.0, values[0]);
  }
  Stability v = classify_stability(index, lowest, so.critical_tolerance, "the beam");
  v.message = fmt::format(
      "{} (the contact point s = {:.9g} held along the stop's normal by the force {:.6g}, rolling "
      "term P/|kappa| = {:.6g})",
      v.message,
      point_s_,
      point_P_,
      rolling);
  return v;
}

ContactResult ContactRun::run() {
  ContactResult out;
  out.surface = surface_.type;
  out.steps = options_.steps;
  double lambda_prev = 0.0;
  double interior = 0.0;
  double variable = 0.0;  // s_c, R_n or s_p of the last contact state
  try {
    auto solve_contact = [&](double lambda, double guess) -> double {
      const SegmentChain c = chain_at(lambda);
      switch (mode_) {
        case ContactMode::kWrap:
          return solve_wrap(c, guess);
        case ContactMode::kTip:
          return solve_tip_reaction(c, guess);
        case ContactMode::kPoint:
          solve_point(c);
          return point_s_;
        case ContactMode::kLying:
          solve_lying(c);
          return lying_a_;
        default:
          throw ContactFailure("no contact mode");
      }
    };
    // The wrap's free state may still cross the circle away from the clamp (its indicator is the
    // root curvature); a contact state must not cross the surface anywhere else.
    auto check_gap = [&](double lambda, double gap, bool contact) {
      if (gap < -options_.gap_tolerance * length_) {
        throw ContactFailure(fmt::format(
            "at load factor {:.6g} the beam, {}, would cross the {} at a second place near s = "
            "{:.6g} (gap {:.3g}): {} is not implemented",
            lambda,
            contact ? contact_description(variable) : "free of it",
            surface_name(),
            min_gap_s_,
            gap,
            contact ? "more than one contact" : "contact of an interior point with this circle"));
      }
    };
    auto separation = [&](bool contact, double v) {
      if (!contact) return 0.0;
      return mode_ == ContactMode::kTip ? length_ : v;
    };
    // A tip on a stop whose tangent turns past the stop's opens into a line contact (and closes
    // back): chi = t(L) . nu of the tip contact changes sign (rigid_contact.h). chi_prev is its
    // value at chi_lambda, the last load factor with a tip or line contact.
    const bool stop = surface_.type == ContactSurfaceType::kLine;
    double chi_prev = 0.0, chi_lambda = 0.0;
    auto open_or_close = [&](double lambda) {
      const double chi = tip_slope(lambda);
      const bool lying = chi > 0.0;
      if (lying != (mode_ == ContactMode::kLying)) {
        const ScalarRootResult root = brent_root([&](double l) { return tip_slope(l); },
                                                 chi_lambda,
                                                 lambda,
                                                 chi_prev,
                                                 chi,
                                                 ScalarRootOptions{options_.event_tolerance, 200});
        if (!root.converged()) {
          throw ContactFailure("the opening of the tip contact into a line did not converge");
        }
        out.events.push_back(ContactEvent{
            lying ? ContactEventKind::kLineContact : ContactEventKind::kTipContact, root.x});
        if (lying) {
          // At the opening the line contact is the tip contact: a = L, R_a = R_n - R_L.
          tip_slope(root.x);
          const SegmentChain at = chain_at(root.x);
          check_lying(at);
          tau_ = V2(normal_.y(), -normal_.x());
          const ShootingResult r = shoot(with_reaction(at, tip_Rn_), false);
          if (std::cos(r.tip.theta) * tau_.x() + std::sin(r.tip.theta) * tau_.y() < 0.0) {
            tau_ = -tau_;
          }
          lying_a_ = length_;
          lying_R_ = tip_Rn_ - lying_statics(at, length_).tip_reaction;
          mode_ = ContactMode::kLying;
        } else {
          tip_slope(lambda);
          variable = tip_Rn_;
          mode_ = ContactMode::kTip;
        }
      }
      chi_prev = chi;
      chi_lambda = lambda;
    };
    double psi_prev = indicator(0.0, &interior);
    bool contact = psi_prev < 0.0;
    if (contact) {
      mode_ = landing_mode(0.0);
      if (stop && mode_ == ContactMode::kTip) {
        chi_prev = tip_slope(0.0);
        if (chi_prev > 0.0) {
          throw ContactFailure(
              "the beam lies on the stop at the start load (line contact at load factor 0): "
              "start from a load with the tip alone on the stop, or none");
        }
      }
      variable = solve_contact(0.0, 0.0);
    } else if (wrap_) {
      check_gap(0.0, interior, false);
    }
    out.path.push_back(
        ContactPathPoint{0.0, contact, separation(contact, variable), 0.0, psi_prev, {}});
    for (int k = 1; k <= options_.steps; ++k) {
      const double lambda = static_cast<double>(k) / options_.steps;
      const double psi = indicator(lambda, &interior);
      const bool now = psi < 0.0;
      if (now != contact) {
        const ScalarRootResult root = brent_root([&](double l) { return indicator(l); },
                                                 lambda_prev,
                                                 lambda,
                                                 psi_prev,
                                                 psi,
                                                 ScalarRootOptions{options_.event_tolerance, 200});
        if (!root.converged()) throw ContactFailure("a landing or lift-off point did not converge");
        out.events.push_back(
            ContactEvent{now ? ContactEventKind::kLanding : ContactEventKind::kLiftOff, root.x});
        if (now) {
          variable = 0.0;
          mode_ = landing_mode(lambda);
          if (stop && mode_ == ContactMode::kTip) {
            tip_Rn_ = 0.0;
            chi_prev = tip_slope(root.x);
            chi_lambda = root.x;
          }
        } else {
          mode_ = ContactMode::kNone;
        }
      }
      contact = now;
      if (!contact) {
        if (wrap_) check_gap(lambda, interior, false);
        variable = 0.0;
      } else {
        if (stop && (mode_ == ContactMode::kTip || mode_ == ContactMode::kLying)) {
          open_or_close(lambda);
        }
        variable = solve_contact(lambda, variable);
      }
      ContactResult step;
      fill(lambda, contact, variable, step);
      if (other_gap_ < -options_.gap_tolerance * length_) {
        const RigidSurface& o = others_[static_cast<std::size_t>(other_index_)];
        throw ContactFailure(fmt::format(
            "at load factor {:.6g} the beam, {}, would cross the {} (contact {}) near s = {:.6g} "
            "(gap {:.3g}): {}",
            lambda,
            contact_description(variable),
            to_string(o.type),
            other_ids_[static_cast<std::size_t>(other_index_)],
            other_s_,
            other_gap_,
            contact ? "several contacts at once are not implemented"
            : out.events.empty()
                ? "the beam meets that surface first"
                : "landing on another surface after leaving this one is not implemented (one "
                  "surface per continuation)"));
      }
      if (contact) {
        check_gap(lambda, step.min_gap, true);
        if (step.point_force_normal < -1e-9 * std::max(1.0, std::abs(step.point_force_normal))) {
          throw ContactFailure(
              fmt::format("at load factor {:.6g} the contact force would pull ({:.3g})",
                          lambda,
                          step.point_force_normal));
        }
      }
      out.path.push_back(ContactPathPoint{
          lambda, contact, separation(contact, variable), step.point_force_normal, psi, step.tip});
      lambda_prev = lambda;
      psi_prev = psi;
      out.load_factor = lambda;
    }
    fill(1.0, contact, variable, out);
    if (options_.judge_stability) {
      try {
        out.stability = verdict(contact, variable);
      } catch (const InvalidInput& e) {
        out.stability = not_checked_stability(e.what());
      } catch (const NoConvergence& e) {
        out.stability = not_checked_stability(e.what());
      }
    } else {
      out.stability = not_checked_stability("the verdict was switched off");
    }
    out.kind = !contact                       ? ContactKind::kNone
               : mode_ == ContactMode::kWrap  ? ContactKind::kWrap
               : mode_ == ContactMode::kTip   ? ContactKind::kTip
               : mode_ == ContactMode::kLying ? ContactKind::kLine
                                              : ContactKind::kPoint;
    out.set_converged(true);
    out.message = contact ? fmt::format("in contact with the {}", to_string(surface_.type))
                          : fmt::format("free of the {}", to_string(surface_.type));
  } catch (const ContactFailure& e) {
    out.termination = Termination::kNoConvergence;
    out.load_factor = lambda_prev;
    out.message = fmt::format("contact with the {} stopped after load factor {:.6g}: {}",
                              to_string(surface_.type),
                              lambda_prev,
                              e.what());
  }
  out.shooting_solves = solves_;
  return out;
}

}  // namespace

ContactResult RigidContactSolver::solve(const SegmentChain& chain,
                                        const RigidSurface& surface,
                                        const TipLoad& start_tip_load) const {
  options_.validate();
  ContactRun run(chain, surface, start_tip_load, options_);
  return run.run();
}

ContactResult RigidContactSolver::solve(const SegmentChain& chain,
                                        const std::vector<RigidSurface>& surfaces,
                                        const TipLoad& start_tip_load) const {
  options_.validate();
  if (surfaces.empty()) throw InvalidInput("contact: no surface given");
  if (surfaces.size() == 1) return solve(chain, surfaces.front(), start_tip_load);
  // One continuation per surface, every other surface checked for crossing at each step: the run
  // whose surface is the one touched (or any, with none touched) holds along the whole path.
  std::vector<ContactRun> runs;
  runs.reserve(surfaces.size());
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    runs.emplace_back(chain, surfaces[i], start_tip_load, options_);  // validates every surface
    std::vector<RigidSurface> others;
    std::vector<int> ids;
    for (std::size_t j = 0; j < surfaces.size(); ++j) {
      if (j == i) continue;
      others.push_back(surfaces[j]);
      ids.push_back(static_cast<int>(j) + 1);
    }
    runs.back().set_others(static_cast<int>(i) + 1, std::move(others), std::move(ids));
  }
  std::optional<ContactResult> touched, free, failed;
  std::vector<std::string> failures;
  long solves = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    ContactResult r = runs[i].run();
    r.surface_index = static_cast<int>(i);
    solves += r.shooting_solves;
    if (r.converged()) {
      if (r.in_contact && !touched) touched = std::move(r);
      if (!r.in_contact && !free) free = std::move(r);
    } else {
      failures.push_back(r.message);
      if (!failed || r.load_factor > failed->load_factor) failed = std::move(r);
    }
  }
  if (touched || free) {
    ContactResult out = touched ? std::move(*touched) : std::move(*free);
    out.shooting_solves = solves;
    return out;
  }
  // Every run met a second surface: the furthest one's failure first, then the others'.
  ContactResult out = std::move(*failed);
  const std::string first = out.message;
  for (const std::string& m : failures) {
    if (m != first) out.message += "; and " + m;
  }
  out.shooting_solves = solves;
  return out;
}

}  // namespace flexure
