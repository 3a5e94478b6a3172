// Frictionless contact with a rigid circle (wrap from the clamp) or a straight stop (tip contact):
// see rigid_contact.h and docs/contact.md for the equations.
#include "flexure/solver/shooting/rigid_contact.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <variant>

#include "flexure/solver/common/errors.h"
#include "flexure/solver/common/scalar_root.h"

namespace flexure {

const char* to_string(ContactSurfaceType type) {
  return type == ContactSurfaceType::kCircle ? "circle" : "line";
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

// A solve that the contact model cannot complete (non-convergence of a free-span solve, no
// separation point): reported as the result's message.
struct ContactFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

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

 private:
  void validate();
  SegmentChain chain_at(double lambda) const;
  ShootingResult shoot(const SegmentChain& chain, bool sampled);
  // psi(lambda) < 0 where contact holds (rigid_contact.h); also the free solution's minimum gap.
  double indicator(double lambda, double* interior_gap = nullptr);
  double gap_of(const V2& r) const;
  double min_gap(const std::vector<ShapePoint>& shape, bool skip_last, bool skip_root) const;

  // Circle: the wrap pose at s, the free span solved from s, its curvature residual.
  ChainPose wrap_pose(double s) const;
  SegmentChain span_chain(const SegmentChain& chain, double s_c) const;
  double curvature_residual(const SegmentChain& chain, double s_c);
  double solve_wrap(const SegmentChain& chain, double guess);
  // Line: the tip gap with a normal reaction R_n at the tip.
  SegmentChain with_reaction(const SegmentChain& chain, double Rn) const;
  double tip_gap(const SegmentChain& chain, double Rn);
  double solve_tip_reaction(const SegmentChain& chain, double guess);

  void fill(double lambda, bool contact, double variable, ContactResult& out);

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
  // line
  V2 point_ = V2::Zero();
  V2 normal_ = V2(0, 1);
  long solves_ = 0;
};

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
    // Tangent at the clamp: the centre lies on the clamp's normal at distance R.
    if (std::abs(cx) > 1e-9 * R || std::abs(std::abs(cy) - R) > 1e-9 * R) {
      throw InvalidInput(fmt::format(
          "contact circle: center ({:g}, {:g}) with radius {:g} does not touch the beam at the "
          "clamp; the wrap model needs the circle tangent to the beam at the root, centre (0, "
          "+R) or (0, -R) in the root frame (a circle elsewhere is not implemented)",
          cx,
          cy,
          R));
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

double ContactRun::min_gap(const std::vector<ShapePoint>& shape,
                           bool skip_last,
                           bool skip_root) const {
  double g = std::numeric_limits<double>::infinity();
  const std::size_t n = shape.size();
  for (std::size_t i = skip_root ? 1 : 0; i + (skip_last ? 1 : 0) < n; ++i) {
    g = std::min(g, gap_of(V2(shape[i].x, shape[i].y)));
  }
  return g;
}

double ContactRun::indicator(double lambda, double* interior_gap) {
  const SegmentChain c = chain_at(lambda);
  const ShootingResult r = shoot(c, interior_gap != nullptr);
  if (surface_.type == ContactSurfaceType::kCircle) {
    const double m0 = -r.reaction.M;
    if (interior_gap) *interior_gap = min_gap(r.shape, false, true);
    return EI_ / radius_ - sigma_ * m0;
  }
  if (interior_gap) *interior_gap = min_gap(r.shape, true, false);
  return gap_of(V2(r.tip.x, r.tip.y));
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
  const V2 f = rotate(-theta_c, V2(chain.tip_load.Fx, chain.tip_load.Fy));
  span.tip_load.Fx = f.x();
  span.tip_load.Fy = f.y();
  for (NodeLoad& load : span.node_loads) {
    const V2 g = rotate(-theta_c, V2(load.Fx, load.Fy));
    load.Fx = g.x();
    load.Fy = g.y();
  }
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
  out.separation_moment = out.curvature_condition = 0.0;
  const int n_shape = options_.shape_points;
  if (surface_.type == ContactSurfaceType::kCircle) {
    if (!contact) {
      ShootingSolver::Options o = sampled_options_;
      const ShootingResult r = ShootingSolver(o).solve(chain);
      ++solves_;
      if (!r.converged()) throw ContactFailure("the free beam did not converge: " + r.message);
      out.tip = r.tip;
      out.reaction = r.reaction;
      out.min_gap = min_gap(r.shape, false, true);
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

ContactResult ContactRun::run() {
  ContactResult out;
  out.surface = surface_.type;
  out.steps = options_.steps;
  const bool circle = surface_.type == ContactSurfaceType::kCircle;
  double lambda_prev = 0.0;
  double interior = 0.0;
  double variable = 0.0;  // s_c or R_n of the last contact state
  try {
    double psi_prev = indicator(0.0, &interior);
    bool contact = psi_prev < 0.0;
    auto solve_contact = [&](double lambda, double guess) {
      const SegmentChain c = chain_at(lambda);
      return circle ? solve_wrap(c, guess) : solve_tip_reaction(c, guess);
    };
    auto check_free = [&](double lambda, double gap) {
      if (gap < -options_.gap_tolerance * length_) {
        throw ContactFailure(fmt::format(
            "at load factor {:.6g} the beam would cross the {} {} (gap {:.3g}): contact of an "
            "interior point is not implemented",
            lambda,
            to_string(surface_.type),
            circle ? "away from the clamp" : "before its tip",
            gap));
      }
    };
    if (!contact) check_free(0.0, interior);
    if (contact) variable = solve_contact(0.0, 0.0);
    out.path.push_back(ContactPathPoint{0.0, contact, circle ? variable : 0.0, 0.0, psi_prev, {}});
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
        out.events.push_back(ContactEvent{now ? "landing" : "lift-off", root.x});
        if (now) variable = 0.0;
      }
      contact = now;
      if (!contact) {
        check_free(lambda, interior);
        variable = 0.0;
      } else {
        variable = solve_contact(lambda, variable);
      }
      ContactResult step;
      fill(lambda, contact, variable, step);
      if (contact) check_free(lambda, step.min_gap);
      out.path.push_back(ContactPathPoint{lambda,
                                          contact,
                                          contact ? (circle ? variable : length_) : 0.0,
                                          step.point_force_normal,
                                          psi,
                                          step.tip});
      lambda_prev = lambda;
      psi_prev = psi;
      out.load_factor = lambda;
    }
    fill(1.0, contact, variable, out);
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

}  // namespace flexure
