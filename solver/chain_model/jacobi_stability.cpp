#include "flexure/solver/chain_model/jacobi_stability.h"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <variant>

#include "flexure/solver/common/gsl_guard.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

// State layout. Prepare pass: theta, m, G = int ds/EI, Gamma = int max(0, -w) G ds and the Gram
// matrix of (sin, cos) over the movable part. Count pass: theta, m, the Pruefer angle, the
// homogeneous Jacobi solution (u, EI u'), two particular solutions and the integrals of the
// constraint functions against them.
enum : int { kTheta = 0, kM = 1 };
enum : int { kG = 2, kGamma = 3, kGram00 = 4, kGram01 = 5, kGram11 = 6, kPrepareSize = 7 };
enum : int {
  kPhi = 2,
  kUh = 3,
  kVh = 4,
  kUp = 5,       // u_p[a] = y[kUp + 2a], v_p[a] = y[kUp + 2a + 1]
  kIh = 9,       // int g_a u_h
  kIp = 11,      // int g_a u_p[b] = y[kIp + 2a + b]
  kGrowth = 15,  // int sqrt(sigma max(0, N . t) / EI) ds: how much the Jacobi solutions grow
  kCountSize = 16,
};

struct Segment_ {
  const FlexibleSegment* flexible = nullptr;  // null: rigid link
  double length = 0.0;                        // scaled
  double angle_offset = 0.0;
  double Nx = 0.0, Ny = 0.0;  // scaled internal force
  double node_moment = 0.0;   // scaled dead moment at the near node (dropped from m there)
  bool movable = false;       // eta can be nonzero on it
};

struct Context {
  std::vector<Segment_> segments;
  double length_scale = 1.0, stiffness_scale = 1.0;
  const SegmentAngle* theta = nullptr;  // null: integrate the elastica
  bool prepare = true;
  double sigma = 1.0;
  int constraints = 0;  // 0..2 in the count pass
  std::array<std::array<double, 2>, 2> combination{};
  // The segment being integrated.
  int segment = 0;
  double piece_start = 0.0;  // unscaled local arc length where the current piece starts
};

double angle_at(const Context& c, const double* y, double s_local) {
  return c.theta != nullptr ? (*c.theta)(c.segment, s_local) : y[kTheta];
}

int rhs(double t, const double y[], double dydt[], void* params) {
  const Context& c = *static_cast<const Context*>(params);
  const Segment_& seg = c.segments[static_cast<std::size_t>(c.segment)];
  const double s_local = c.piece_start + t * c.length_scale;
  const double EI = seg.flexible->EI_at(s_local) / c.stiffness_scale;
  const double theta = angle_at(c, y, s_local);
  const double sn = std::sin(theta), cs = std::cos(theta);
  dydt[kTheta] = y[kM] / EI + seg.flexible->kappa0 * c.length_scale;
  dydt[kM] = seg.Nx * sn - seg.Ny * cs;
  const double w = seg.Nx * cs + seg.Ny * sn;
  if (c.prepare) {
    dydt[kG] = 1.0 / EI;
    dydt[kGamma] = std::max(0.0, -w) * y[kG];
    dydt[kGram00] = sn * sn;
    dydt[kGram01] = sn * cs;
    dydt[kGram11] = cs * cs;
    return GSL_SUCCESS;
  }
  std::fill(dydt + kPhi, dydt + kCountSize, 0.0);  // the unused constraint states stay 0
  const double sp = std::sin(y[kPhi]), cp = std::cos(y[kPhi]);
  dydt[kPhi] = cp * cp / EI - c.sigma * w * sp * sp;
  dydt[kUh] = y[kVh] / EI;
  dydt[kVh] = c.sigma * w * y[kUh];
  dydt[kGrowth] = std::sqrt(c.sigma * std::max(0.0, w) / EI);
  for (int a = 0; a < c.constraints; ++a) {
    const double g = c.combination[a][0] * sn + c.combination[a][1] * cs;
    dydt[kUp + 2 * a] = y[kUp + 2 * a + 1] / EI;
    dydt[kUp + 2 * a + 1] = c.sigma * w * y[kUp + 2 * a] - g;
  }
  for (int a = 0; a < c.constraints; ++a) {
    const double g = c.combination[a][0] * sn + c.combination[a][1] * cs;
    dydt[kIh + a] = g * y[kUh];
    for (int b = 0; b < c.constraints; ++b) dydt[kIp + 2 * a + b] = g * y[kUp + 2 * b];
  }
  return GSL_SUCCESS;
}

// A rigid link of scaled length l: theta constant, eta constant, the rest changes linearly.
void rigid_link(Context& c, const Segment_& seg, double* y) {
  const double l = seg.length;
  const double theta = c.theta != nullptr ? (*c.theta)(c.segment, 0.0) : y[kTheta];
  const double sn = std::sin(theta), cs = std::cos(theta);
  const double w = seg.Nx * cs + seg.Ny * sn;
  y[kM] += l * (seg.Nx * sn - seg.Ny * cs);
  if (c.prepare) {
    y[kGamma] += l * std::max(0.0, -w) * y[kG];
    if (seg.movable) {
      y[kGram00] += l * sn * sn;
      y[kGram01] += l * sn * cs;
      y[kGram11] += l * cs * cs;
    }
    return;
  }
  // Pruefer angle: u is constant, so phi stays between the same multiples of pi.
  const double before = std::atan2(y[kUh], y[kVh]);
  y[kVh] += l * c.sigma * w * y[kUh];
  if (y[kUh] != 0.0) y[kPhi] += std::atan2(y[kUh], y[kVh]) - before;
  for (int a = 0; a < c.constraints; ++a) {
    const double g = c.combination[a][0] * sn + c.combination[a][1] * cs;
    y[kIh + a] += l * g * y[kUh];
    for (int b = 0; b < c.constraints; ++b) y[kIp + 2 * a + b] += l * g * y[kUp + 2 * b];
  }
  for (int a = 0; a < c.constraints; ++a) {
    const double g = c.combination[a][0] * sn + c.combination[a][1] * cs;
    y[kUp + 2 * a + 1] += l * (c.sigma * w * y[kUp + 2 * a] - g);
  }
}

// Integrates the state along the chain from the clamp to the tip.
void sweep(Context& c, const JacobiStabilityOptions& options, double* y, std::size_t size) {
  disable_gsl_abort();
  gsl_odeiv2_system system{rhs, nullptr, size, &c};
  std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> driver(
      gsl_odeiv2_driver_alloc_y_new(
          &system, gsl_odeiv2_step_rk8pd, 1e-3, options.atol, options.rtol),
      &gsl_odeiv2_driver_free);
  if (!driver) throw NoConvergence("the Jacobi check could not allocate its integrator");
  gsl_odeiv2_driver_set_nmax(driver.get(), 2000000);
  for (std::size_t j = 0; j < c.segments.size(); ++j) {
    const Segment_& seg = c.segments[j];
    c.segment = static_cast<int>(j);
    y[kM] -= seg.node_moment;
    if (seg.flexible == nullptr) {
      if (c.theta == nullptr) y[kTheta] += seg.angle_offset;
      if (seg.length > 0.0) rigid_link(c, seg, y);
      continue;
    }
    // Pieces between the EI profile's stations (its kinks).
    const double length = seg.length * c.length_scale;
    const int pieces = seg.flexible->EI_profile.size() >= 2
                           ? static_cast<int>(seg.flexible->EI_profile.size()) - 1
                           : 1;
    for (int p = 0; p < pieces; ++p) {
      c.piece_start = length * p / pieces;
      const double piece_end = length * (p + 1) / pieces;
      double t = 0.0;
      const double t_end = (piece_end - c.piece_start) / c.length_scale;
      gsl_odeiv2_driver_reset(driver.get());
      gsl_odeiv2_driver_reset_hstart(driver.get(), std::min(1e-3, 0.1 * t_end));
      const int status = gsl_odeiv2_driver_apply(driver.get(), &t, t_end, y);
      if (status != GSL_SUCCESS) {
        throw NoConvergence(fmt::format(
            "the Jacobi check's integration failed on segment {} (GSL status {})", j + 1, status));
      }
    }
  }
}

}  // namespace

void JacobiStabilityOptions::validate() const {
  if (!(rtol >= 1e-15 && rtol <= 1e-4)) {
    throw InvalidInput(fmt::format("Jacobi check rtol must be in [1e-15, 1e-4] (got {})", rtol));
  }
  if (!(atol > 0.0 && atol <= 1e-4)) {
    throw InvalidInput(fmt::format("Jacobi check atol must be in (0, 1e-4] (got {})", atol));
  }
  if (!(eigenvalue_tolerance >= 1e-15 && eigenvalue_tolerance <= 1e-2)) {
    throw InvalidInput(
        fmt::format("Jacobi check eigenvalue_tolerance must be in [1e-15, 1e-2] (got {})",
                    eigenvalue_tolerance));
  }
  if (!(critical_tolerance >= 0.0) || !std::isfinite(critical_tolerance)) {
    throw InvalidInput(
        fmt::format("Jacobi check critical_tolerance must be a finite number >= 0 (got {})",
                    critical_tolerance));
  }
  if (!(max_sigma > 1.0) || !std::isfinite(max_sigma)) {
    throw InvalidInput(
        fmt::format("Jacobi check max_sigma must be a finite number > 1 (got {})", max_sigma));
  }
}

JacobiSecondVariation::JacobiSecondVariation(const SegmentChain& chain,
                                             const Reaction& root_reaction,
                                             JacobiStabilityOptions options)
    : chain_(chain), options_(options) {
  options_.validate();
  chain_.validate();
  chain_.require_elastica_only("the Jacobi stability test");
  require_finite(root_reaction.Fx, "root reaction Fx");
  require_finite(root_reaction.Fy, "root reaction Fy");
  require_finite(root_reaction.M, "root reaction M");
  Nx0_ = -root_reaction.Fx;
  Ny0_ = -root_reaction.Fy;
  m0_ = -root_reaction.M;
  prepare();
}

JacobiSecondVariation::JacobiSecondVariation(const SegmentChain& chain,
                                             const Reaction& root_reaction,
                                             SegmentAngle theta,
                                             JacobiStabilityOptions options)
    : chain_(chain), options_(options), theta_(std::move(theta)) {
  options_.validate();
  chain_.validate();
  chain_.require_elastica_only("the Jacobi stability test");
  require_finite(root_reaction.Fx, "root reaction Fx");
  require_finite(root_reaction.Fy, "root reaction Fy");
  Nx0_ = -root_reaction.Fx;
  Ny0_ = -root_reaction.Fy;
  prepare();
}

namespace {

// Scaled segment data: N from the root, dropping by each node's load across the node.
std::vector<Segment_> scaled_segments(
    const SegmentChain& chain, double Nx0, double Ny0, double L, double EI) {
  std::vector<Segment_> out;
  const PrescribedMask mask = prescribed_mask(chain.end);
  int last_flexible = -1, first_flexible = -1;
  for (std::size_t j = 0; j < chain.segments.size(); ++j) {
    if (std::holds_alternative<FlexibleSegment>(chain.segments[j])) {
      last_flexible = static_cast<int>(j);
      if (first_flexible < 0) first_flexible = static_cast<int>(j);
    }
  }
  double Nx = Nx0, Ny = Ny0;
  for (std::size_t j = 0; j < chain.segments.size(); ++j) {
    Segment_ s;
    double moment = 0.0;
    for (const NodeLoad& load : chain.node_loads) {
      if (static_cast<std::size_t>(load.node) == j) {
        Nx -= load.Fx;
        Ny -= load.Fy;
        moment += load.M;
      }
    }
    s.Nx = Nx * L * L / EI;
    s.Ny = Ny * L * L / EI;
    s.node_moment = moment * L / EI;
    if (const auto* f = std::get_if<FlexibleSegment>(&chain.segments[j])) {
      s.flexible = f;
      s.length = f->length / L;
    } else {
      const auto& r = std::get<RigidSegment>(chain.segments[j]);
      s.length = r.length / L;
      s.angle_offset = r.angle_offset;
    }
    const int jj = static_cast<int>(j);
    s.movable = first_flexible >= 0 && jj >= first_flexible && !(mask.theta && jj > last_flexible);
    out.push_back(s);
  }
  return out;
}

}  // namespace

void JacobiSecondVariation::prepare() {
  follower_ = chain_.tip_load.follower != 0.0;
  length_scale_ = chain_.total_length();
  stiffness_scale_ = HUGE_VAL;
  for (const Segment& segment : chain_.segments) {
    if (const auto* f = std::get_if<FlexibleSegment>(&segment)) {
      flexible_ = true;
      stiffness_scale_ = std::min(
          stiffness_scale_,
          f->EI_profile.size() >= 2 ? *std::min_element(f->EI_profile.begin(), f->EI_profile.end())
                                    : f->EI);
    }
  }
  if (follower_ || !flexible_) return;
  Context c;
  c.segments = scaled_segments(chain_, Nx0_, Ny0_, length_scale_, stiffness_scale_);
  c.length_scale = length_scale_;
  c.stiffness_scale = stiffness_scale_;
  c.theta = theta_ ? &theta_ : nullptr;
  c.prepare = true;
  double y[kPrepareSize] = {0.0, m0_ * length_scale_ / stiffness_scale_, 0, 0, 0, 0, 0};
  sweep(c, options_, y, kPrepareSize);
  compression_bound_ = y[kGamma];
  // Independent constraint combinations: eigenvectors of the Gram matrix of the prescribed rows
  // over the movable part with eigenvalue above 1e-20 (the chain's scaled length is 1).
  const PrescribedMask mask = prescribed_mask(chain_.end);
  combinations_.clear();
  if (mask.x && mask.y) {
    const double g00 = y[kGram00], g01 = y[kGram01], g11 = y[kGram11];
    const double mean = 0.5 * (g00 + g11), radius = std::hypot(0.5 * (g00 - g11), g01);
    for (const double mu : {mean + radius, mean - radius}) {
      if (!(mu > 1e-20)) continue;
      double vx = g01, vy = mu - g00;
      if (std::hypot(mu - g11, g01) > std::hypot(vx, vy)) {
        vx = mu - g11;
        vy = g01;
      }
      const double norm = std::hypot(vx, vy);
      if (!(norm > 0.0)) {
        vx = combinations_.empty() ? 1.0 : 0.0;
        vy = combinations_.empty() ? 0.0 : 1.0;
      } else {
        vx /= norm;
        vy /= norm;
      }
      combinations_.push_back({vx / std::sqrt(mu), vy / std::sqrt(mu)});
    }
  } else if (mask.x) {
    if (y[kGram00] > 1e-20) combinations_.push_back({1.0 / std::sqrt(y[kGram00]), 0.0});
  } else if (mask.y) {
    if (y[kGram11] > 1e-20) combinations_.push_back({0.0, 1.0 / std::sqrt(y[kGram11])});
  }
}

JacobiSecondVariation::CountResult JacobiSecondVariation::evaluate(double lambda,
                                                                   bool constraints) const {
  CountResult r;
  Context c;
  c.segments = scaled_segments(chain_, Nx0_, Ny0_, length_scale_, stiffness_scale_);
  c.length_scale = length_scale_;
  c.stiffness_scale = stiffness_scale_;
  c.theta = theta_ ? &theta_ : nullptr;
  c.prepare = false;
  c.sigma = 1.0 / (1.0 - lambda);
  c.constraints = constraints ? static_cast<int>(combinations_.size()) : 0;
  for (int a = 0; a < c.constraints; ++a) c.combination[a] = combinations_[a];
  double y[kCountSize] = {};
  y[kM] = m0_ * length_scale_ / stiffness_scale_;
  y[kVh] = 1.0;
  sweep(c, options_, y, kCountSize);
  const bool dirichlet = prescribed_mask(chain_.end).theta;
  const double phi = y[kPhi];
  r.growth = y[kGrowth];
  r.unconstrained = static_cast<int>(
      std::floor((dirichlet ? phi : phi + 0.5 * std::numbers::pi) / std::numbers::pi));
  r.constrained = r.unconstrained;
  if (c.constraints == 0) return r;
  // u_b = u_p[b] + alpha_b u_h meets the tip condition; S_ab = int g_a u_b.
  double S[2][2] = {};
  for (int b = 0; b < c.constraints; ++b) {
    const double alpha = dirichlet ? -y[kUp + 2 * b] / y[kUh] : -y[kUp + 2 * b + 1] / y[kVh];
    for (int a = 0; a < c.constraints; ++a) S[a][b] = y[kIp + 2 * a + b] + alpha * y[kIh + a];
  }
  int negative = 0, zero = 0;
  if (c.constraints == 1) {
    negative = S[0][0] < 0.0 ? 1 : 0;
    zero = S[0][0] == 0.0 ? 1 : 0;
  } else {
    const double s01 = 0.5 * (S[0][1] + S[1][0]);
    const double det = S[0][0] * S[1][1] - s01 * s01, trace = S[0][0] + S[1][1];
    if (det < 0.0) {
      negative = 1;
    } else if (det > 0.0) {
      negative = trace < 0.0 ? 2 : 0;
    } else {
      zero = 1;
      negative = trace < 0.0 ? 1 : 0;
    }
  }
  r.constrained = r.unconstrained - negative - zero;
  return r;
}

int JacobiSecondVariation::count(double lambda) const {
  if (follower_ || !flexible_) return 0;
  return evaluate(lambda, true).constrained;
}

double JacobiSecondVariation::growth_exponent(double lambda) const {
  if (follower_ || !flexible_) return 0.0;
  return evaluate(lambda, false).growth;
}

int JacobiSecondVariation::unconstrained_count(double lambda) const {
  if (follower_ || !flexible_) return 0;
  return evaluate(lambda, false).unconstrained;
}

double JacobiSecondVariation::eigenvalue(int k) const {
  if (follower_ || !flexible_ || !(compression_bound_ > 0.0) || k < 1) return 1.0;
  double lo = 1.0 - 1.01 * compression_bound_ - 1e-9;
  double x = 1.0 - 0.5 * compression_bound_;
  int at = count(x);
  while (at < k) {
    lo = x;
    if (1.0 / (1.0 - x) >= options_.max_sigma) return 1.0;
    x = 1.0 - 0.25 * (1.0 - x);
    at = count(x);
  }
  double hi = x;
  while (hi - lo > options_.eigenvalue_tolerance * std::max(1.0, std::fabs(hi))) {
    const double mid = 0.5 * (lo + hi);
    (count(mid) >= k ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

Stability JacobiSecondVariation::verdict() const {
  if (follower_) {
    return not_conservative_stability(
        fmt::format("a follower force of {:.6g} acts at the tip", chain_.tip_load.follower));
  }
  if (!flexible_) {
    return not_checked_stability("the chain has no flexible segment, so it cannot deflect");
  }
  const int index = count(-options_.critical_tolerance);
  return classify_stability(index,
                            eigenvalue(1),
                            options_.critical_tolerance,
                            chain_.segments.size() == 1 ? "the beam" : "the chain");
}

}  // namespace flexure
