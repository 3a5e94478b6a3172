#include "flexure/elements/chained_bcm.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "flexure/elements/beam_constraint_model.h"
#include "flexure/elements/load_path_newton.h"
#include "flexure/solver/chain_model/tip_reach.h"
#include "flexure/solver/common/errors.h"

namespace flexure {
namespace {

struct PointLoad {
  double Fx = 0.0, Fy = 0.0, M = 0.0;
};

// The chain in the flexible segment's units (length L = 1, EI = 1): what the residual needs.
struct Prepared {
  double L = 1.0, EI = 1.0;
  double EA = std::numeric_limits<double>::infinity();   // the segment's (docs/extensible.md)
  double GAs = std::numeric_limits<double>::infinity();  // not modelled: the BCM is shear-rigid
  ChainPose root;                       // the segment's root (placed by the rigid links before it)
  std::vector<RigidSegment> tip_links;  // after the segment, lengths per L
  // Loads on the distal part: [0] at the segment's tip, [i] at the far end of tip link i-1 (the
  // last carries the chain's tip load); per EI/L^2 and EI/L.
  std::vector<PointLoad> distal_loads;
  // Loads on the clamped part before the segment (they pass to the clamp): position per L, load.
  std::vector<std::pair<ChainPose, PointLoad>> root_loads;
  PrescribedMask mask;
  ChainPose target;    // the prescribed tip at full load, per L
  ChainPose unloaded;  // the unloaded tip, per L
  int prescribed = 0;
  double load_scale = 1.0;  // max(1, |loads|, |tip motion|): the residual's scale
};

Prepared prepare(const SegmentChain& chain, const std::string& model) {
  chain.validate();
  int flexible_index = -1;
  int flexible_count = 0;
  for (int i = 0; i < chain.segment_count(); ++i) {
    if (std::holds_alternative<FlexibleSegment>(chain.segments[static_cast<std::size_t>(i)])) {
      ++flexible_count;
      flexible_index = i;
    }
  }
  if (flexible_count != 1) {
    throw InvalidInput(fmt::format(
        "the {} model solves a chain of one flexible segment with rigid links or kinks at either "
        "end (this chain has {} flexible segments); the shooting method or the chain algorithm "
        "solves it",
        model,
        flexible_count));
  }
  const auto& flexible =
      std::get<FlexibleSegment>(chain.segments[static_cast<std::size_t>(flexible_index)]);
  if (flexible.kappa0 != 0.0 || !flexible.EI_profile.empty()) {
    throw InvalidInput(fmt::format(
        "the {} model's elements are straight and uniform: the flexible segment has {}; the "
        "shooting method or the chain algorithm solves it",
        model,
        flexible.kappa0 != 0.0 ? "an initial curvature kappa0" : "an EI profile"));
  }
  if (flexible.has_distributed_load()) {
    throw InvalidInput(fmt::format(
        "the {} model's elements carry end loads only: the flexible segment has a distributed "
        "load (qx, qy, q_profile or q_follower); the shooting method solves it",
        model));
  }
  if (chain.tip_load.follower != 0.0) {
    throw InvalidInput(fmt::format(
        "the {} model takes dead loads; the shooting method solves a follower force", model));
  }
  require_reachable_tip(chain);
  Prepared p;
  p.L = flexible.length;
  p.EI = flexible.EI;
  p.EA = flexible.EA;
  p.GAs = flexible.GAs;
  const double force_scale = p.L * p.L / p.EI, moment_scale = p.L / p.EI;
  const std::vector<ChainPose> unloaded = chain.unloaded_nodes();
  const ChainPose& root = unloaded[static_cast<std::size_t>(flexible_index)];
  p.root = {root.x / p.L, root.y / p.L, root.theta};
  for (int i = flexible_index + 1; i < chain.segment_count(); ++i) {
    RigidSegment link = std::get<RigidSegment>(chain.segments[static_cast<std::size_t>(i)]);
    link.length /= p.L;
    p.tip_links.push_back(link);
  }
  p.distal_loads.resize(p.tip_links.size() + 1);
  const auto scaled = [&](double Fx, double Fy, double M) {
    return PointLoad{Fx * force_scale, Fy * force_scale, M * moment_scale};
  };
  for (const NodeLoad& load : chain.node_loads) {
    const PointLoad l = scaled(load.Fx, load.Fy, load.M);
    if (load.node <= flexible_index) {
      const ChainPose& at = unloaded[static_cast<std::size_t>(load.node)];
      p.root_loads.push_back({{at.x / p.L, at.y / p.L, at.theta}, l});
    } else {
      PointLoad& d = p.distal_loads[static_cast<std::size_t>(load.node - flexible_index - 1)];
      d.Fx += l.Fx;
      d.Fy += l.Fy;
      d.M += l.M;
    }
  }
  PointLoad& tip = p.distal_loads.back();
  const PointLoad t = scaled(chain.tip_load.Fx, chain.tip_load.Fy, chain.tip_load.M);
  tip.Fx += t.Fx;
  tip.Fy += t.Fy;
  tip.M += t.M;
  p.mask = prescribed_mask(chain.end);
  p.prescribed = int(p.mask.x) + int(p.mask.y) + int(p.mask.theta);
  const ChainPose target = chain.prescribed_tip();
  const ChainPose free_tip = chain.unloaded_tip();
  p.target = {target.x / p.L, target.y / p.L, target.theta};
  p.unloaded = {free_tip.x / p.L, free_tip.y / p.L, free_tip.theta};
  double scale = 1.0;
  for (const PointLoad& l : p.distal_loads) {
    scale = std::max({scale, std::fabs(l.Fx), std::fabs(l.Fy), std::fabs(l.M)});
  }
  scale = std::max({scale,
                    std::fabs(p.target.x - p.unloaded.x),
                    std::fabs(p.target.y - p.unloaded.y),
                    std::fabs(p.target.theta - p.unloaded.theta)});
  p.load_scale = scale;
  return p;
}

// The state of the discretised segment for unknowns z at load factor lambda.
struct Evaluation {
  std::vector<ChainPose> nodes;  // N + 1 element nodes (node 0 = the segment's root)
  std::vector<ChainPose> links;  // the far ends of the tip links
  double Fx = 0.0, Fy = 0.0;     // force on the distal part (reactions included)
  double Rx = 0.0, Ry = 0.0, Rm = 0.0;
  double moment_about_origin = 0.0;  // of the distal loads (reactions included)
  ChainPose tip;
};

class Discretisation {
 public:
  Discretisation(const Prepared& prepared, int elements, double inverse_d)
      : p_(prepared), n_(elements), h_(1.0 / elements) {
    set_inverse_axial_stiffness(inverse_d);
  }
  // 1/d of the whole segment (0: inextensible); each element's is N^2/d.
  void set_inverse_axial_stiffness(double inverse_d) { inverse_de_ = inverse_d * n_ * n_; }

  int size() const { return 2 * n_ + p_.prescribed; }

  void evaluate(const Eigen::VectorXd& z, double lambda, Evaluation& e) const {
    int index = 2 * n_;
    e.Rx = p_.mask.x ? z[index++] : 0.0;
    e.Ry = p_.mask.y ? z[index++] : 0.0;
    e.Rm = p_.mask.theta ? z[index++] : 0.0;
    e.Fx = e.Rx;
    e.Fy = e.Ry;
    for (const PointLoad& l : p_.distal_loads) {
      e.Fx += lambda * l.Fx;
      e.Fy += lambda * l.Fy;
    }
    e.nodes.resize(static_cast<std::size_t>(n_ + 1));
    ChainPose at = p_.root;
    e.nodes[0] = at;
    for (int j = 0; j < n_; ++j) {
      const double c = std::cos(at.theta), s = std::sin(at.theta);
      const double y = z[2 * j], theta = z[2 * j + 1];
      const double p_hat = (e.Fx * c + e.Fy * s) * h_ * h_;
      const double x = bcm::axial_displacement(y, theta, p_hat, inverse_de_);
      at.x += h_ * ((1.0 + x) * c - y * s);
      at.y += h_ * ((1.0 + x) * s + y * c);
      at.theta += theta;
      e.nodes[static_cast<std::size_t>(j + 1)] = at;
    }
    const auto moment = [](const ChainPose& where, double Fx, double Fy, double M) {
      return M + where.x * Fy - where.y * Fx;
    };
    const PointLoad& first = p_.distal_loads[0];
    e.moment_about_origin = lambda * moment(at, first.Fx, first.Fy, first.M);
    e.links.clear();
    for (std::size_t i = 0; i < p_.tip_links.size(); ++i) {
      const RigidSegment& link = p_.tip_links[i];
      at.theta += link.angle_offset;
      at.x += link.length * std::cos(at.theta);
      at.y += link.length * std::sin(at.theta);
      e.links.push_back(at);
      const PointLoad& l = p_.distal_loads[i + 1];
      e.moment_about_origin += lambda * moment(at, l.Fx, l.Fy, l.M);
    }
    e.tip = at;
    e.moment_about_origin += moment(at, e.Rx, e.Ry, e.Rm);
  }

  // The BCM relations of every element (per EI/L^2 and EI/L) and the prescribed coordinates.
  void residual(const Eigen::VectorXd& z, double lambda, Evaluation& e, Eigen::VectorXd& r) const {
    evaluate(z, lambda, e);
    r.resize(size());
    for (int j = 0; j < n_; ++j) {
      const ChainPose& root = e.nodes[static_cast<std::size_t>(j)];
      const ChainPose& tip = e.nodes[static_cast<std::size_t>(j + 1)];
      const double c = std::cos(root.theta), s = std::sin(root.theta);
      const double p_hat = (e.Fx * c + e.Fy * s) * h_ * h_;
      const double f_hat = (-e.Fx * s + e.Fy * c) * h_ * h_;
      // The distal loads' moment about the element's tip node.
      const double m_hat = (e.moment_about_origin - (tip.x * e.Fy - tip.y * e.Fx)) * h_;
      const bcm::Symmetric2 K = bcm::stiffness(p_hat);
      const double y = z[2 * j], theta = z[2 * j + 1];
      r[2 * j] = (K.a11 * y + K.a12 * theta - f_hat) / (h_ * h_);
      r[2 * j + 1] = (K.a12 * y + K.a22 * theta - m_hat) / h_;
    }
    int index = 2 * n_;
    const auto target = [&](double unloaded, double prescribed) {
      return unloaded + lambda * (prescribed - unloaded);
    };
    if (p_.mask.x) r[index++] = e.tip.x - target(p_.unloaded.x, p_.target.x);
    if (p_.mask.y) r[index++] = e.tip.y - target(p_.unloaded.y, p_.target.y);
    if (p_.mask.theta) r[index++] = e.tip.theta - target(p_.unloaded.theta, p_.target.theta);
  }

  int elements() const { return n_; }

 private:
  const Prepared& p_;
  int n_;
  double h_;
  double inverse_de_;  // 1/d of one element: N^2/d
};

// The segment's axial stiffness d = EA L^2/EI (12 (L/t)^2 for a rectangle): its own EA, else the
// slenderness option's, else infinity (the inextensible elastica).
double axial_stiffness(const Prepared& p, double slenderness, const std::string& model) {
  if (std::isfinite(p.EA)) {
    const double d = p.EA * p.L * p.L / p.EI;
    if (slenderness > 0.0) {
      throw InvalidInput(fmt::format(
          "the {} model takes its axial stiffness from the flexible segment's EA = {:g} (d = EA "
          "L^2/EI = {:g}) and from a slenderness L/t = {:g} (d = 12 (L/t)^2 = {:g}): give one "
          "(leave "
          "out the slenderness to use EA)",
          model,
          p.EA,
          d,
          slenderness,
          12.0 * slenderness * slenderness));
    }
    return d;
  }
  if (slenderness > 0.0) return 12.0 * slenderness * slenderness;
  return std::numeric_limits<double>::infinity();
}

}  // namespace

void ChainedBcmSolver::Options::validate() const {
  if (elements < 1 || elements > 2000) {
    throw InvalidInput(
        fmt::format("the chained BCM's number of elements must be 1 to 2000 (got {})", elements));
  }
  if (!std::isfinite(slenderness) || slenderness < 0.0) {
    throw InvalidInput(fmt::format(
        "the slenderness L/t must be 0 (inextensible) or finite and > 0 (got {})", slenderness));
  }
  if (!std::isfinite(tolerance) || !(tolerance > 0.0)) {
    throw InvalidInput(
        fmt::format("the chained BCM's tolerance must be finite and > 0 (got {})", tolerance));
  }
  if (max_iterations < 1 || max_load_steps < 1) {
    throw InvalidInput("the chained BCM's max_iterations and max_load_steps must be >= 1");
  }
}

ChainedBcmSolver::ChainedBcmSolver() : ChainedBcmSolver(Options{}) {}

ChainedBcmSolver::ChainedBcmSolver(Options options) : options_(options) { options_.validate(); }

std::string ChainedBcmSolver::model_name() const { return options_.elements == 1 ? "bcm" : "cbcm"; }

CbcmResult ChainedBcmSolver::solve(const CantileverCase& problem) const {
  problem.validate(model_name());
  return solve(problem.to_chain());
}

CbcmResult ChainedBcmSolver::solve(const SegmentChain& chain) const {
  const Prepared prepared = prepare(chain, model_name());
  const double d = axial_stiffness(prepared, options_.slenderness, model_name());
  const double inverse_d = 1.0 / d;  // 0 for the inextensible segment
  Discretisation model(prepared, options_.elements, inverse_d);
  Evaluation scratch;
  const auto residual = [&](const Eigen::VectorXd& z, double lambda, Eigen::VectorXd& r) {
    model.residual(z, lambda, scratch, r);
    return r.allFinite();
  };
  const int n = options_.elements;
  // Every element node's angle (load_path_newton.h watches each).
  const detail::MeasureFunction node_angles = [n](const Eigen::VectorXd& z) -> Eigen::VectorXd {
    Eigen::VectorXd angles(n);
    double angle = 0.0;
    for (int j = 0; j < n; ++j) angles[j] = angle += z[2 * j + 1];
    return angles;
  };
  detail::LoadPathOptions path;
  path.tolerance = options_.tolerance * prepared.load_scale;
  path.max_iterations = options_.max_iterations;
  path.max_load_steps = options_.max_load_steps;
  Eigen::VectorXd z = Eigen::VectorXd::Zero(model.size());
  detail::LoadPathOutcome outcome =
      detail::follow_load_path(z, residual, nullptr, node_angles, path);
  if (!outcome.converged && outcome.load_steps == 0 && inverse_d == 0.0 &&
      prepared.prescribed > 0) {
    // An inextensible segment whose prescribed tip must approach the root from the start has no
    // regular first step: its shortening is second order in the deflection, so the deflection
    // grows like the square root of the load factor. Two stages, as the shooting method's for a
    // straight chain between two prescribed ends: (1) the path with a finite axial stiffness,
    // d = 1000 (a thick beam, L/t of about 9), regular from the unloaded chain; (2) at full load,
    // the axial compliance 1/d taken to 0 -- the deflected segment is regular there.
    constexpr double kRegularisingInverseD = 1e-3;
    z.setZero();
    model.set_inverse_axial_stiffness(kRegularisingInverseD);
    const detail::LoadPathOutcome first =
        detail::follow_load_path(z, residual, nullptr, node_angles, path);
    if (first.converged) {
      const auto stiffen = [&](const Eigen::VectorXd& state, double t, Eigen::VectorXd& r) {
        model.set_inverse_axial_stiffness((1.0 - t) * kRegularisingInverseD);
        model.residual(state, 1.0, scratch, r);
        return r.allFinite();
      };
      outcome = detail::follow_load_path(z, stiffen, nullptr, node_angles, path);
      outcome.iterations += first.iterations;
      outcome.load_steps += first.load_steps;
      if (!outcome.converged) {
        outcome.message = fmt::format(
            "the second stage (from a finite axial stiffness to the inextensible segment) stopped "
            "at {:.6g} of the way: {}",
            outcome.load_factor,
            outcome.message);
        outcome.load_factor = 0.0;
      }
    } else {
      outcome = first;
      outcome.load_factor = 0.0;
    }
    model.set_inverse_axial_stiffness(0.0);
  }

  CbcmResult out;
  out.elements = n;
  out.iterations = outcome.iterations;
  out.residual = outcome.residual;
  out.load_steps = outcome.load_steps;
  out.load_factor = outcome.load_factor;
  out.set_converged(outcome.converged);
  out.message = outcome.converged
                    ? fmt::format("proportional loading in {} step{}, {} BCM element{}",
                                  outcome.load_steps,
                                  outcome.load_steps == 1 ? "" : "s",
                                  n,
                                  n == 1 ? "" : "s")
                    : outcome.message;
  if (!outcome.converged && inverse_d == 0.0 && prepared.prescribed > 0) {
    // The inextensible segment shortens only by bending: a prescribed tip that pushes it along
    // its axis has no equilibrium near the straight segment (docs/extensible.md).
    // The generic message's guess (a fold, a load the model cannot carry) is replaced: here the
    // likelier cause is the missing axial compliance.
    const std::string hint = fmt::format(
        "the flexible segment is inextensible (no EA) and its tip coordinates are prescribed: "
        "where they compress it along its axis the {} model has no equilibrium near the straight "
        "segment; give the segment's EA (docs/extensible.md) or a slenderness L/t",
        model_name());
    out.message =
        out.message.rfind("the load path could not be followed", 0) == 0
            ? fmt::format("the load path could not be followed past load factor {:.6g}: {}",
                          outcome.load_factor,
                          hint)
            : out.message + "; " + hint;
  }
  out.axial_stiffness = d;
  const double lambda = outcome.load_factor;
  Evaluation e;
  model.evaluate(z, lambda, e);
  const double L = prepared.L;
  const double force_unit = prepared.EI / (L * L), moment_unit = prepared.EI / L;
  out.tip = {e.tip.x * L, e.tip.y * L, e.tip.theta};
  // The clamp holds everything: the distal loads and the loads on the clamped links.
  double Fx = e.Fx, Fy = e.Fy, M = e.moment_about_origin;
  for (const auto& [at, l] : prepared.root_loads) {
    Fx += lambda * l.Fx;
    Fy += lambda * l.Fy;
    M += lambda * (l.M + at.x * l.Fy - at.y * l.Fx);
  }
  out.reaction = {-Fx * force_unit, -Fy * force_unit, -M * moment_unit};
  out.root_moment = M * moment_unit;
  const PointLoad& given = prepared.distal_loads.back();
  out.tip_load = {(lambda * given.Fx + e.Rx) * force_unit,
                  (lambda * given.Fy + e.Ry) * force_unit,
                  (lambda * given.M + e.Rm) * moment_unit};
  // The shape: clamped links, element nodes, tip links.
  const std::vector<ChainPose> unloaded = chain.unloaded_nodes();
  double s = 0.0;
  std::size_t segment = 0;
  out.nodes.push_back({0.0, 0.0, 0.0, 0.0});
  for (; segment < chain.segments.size() &&
         std::holds_alternative<RigidSegment>(chain.segments[segment]);
       ++segment) {
    s += std::get<RigidSegment>(chain.segments[segment]).length;
    const ChainPose& at = unloaded[segment + 1];
    out.nodes.push_back({s, at.x, at.y, at.theta});
  }
  for (int j = 1; j <= n; ++j) {
    const ChainPose& at = e.nodes[static_cast<std::size_t>(j)];
    out.nodes.push_back({s + L * j / n, at.x * L, at.y * L, at.theta});
  }
  s += L;
  for (std::size_t i = 0; i < e.links.size(); ++i) {
    s += prepared.tip_links[i].length * L;
    out.nodes.push_back({s, e.links[i].x * L, e.links[i].y * L, e.links[i].theta});
  }
  for (int j = 0; j < n; ++j) {
    out.max_element_deflection = std::max(out.max_element_deflection, std::fabs(z[2 * j]));
  }
  out.inside_validity = out.max_element_deflection <= bcm::kValidDeflection;
  if (std::isfinite(prepared.GAs)) {
    // Shear adds P L/GAs to a cantilever's tip against the bending P L^3/(3 EI)
    // (docs/extensible.md): the ratio 3 EI/(GAs L^2) says what the BCM leaves out.
    out.warn(WarningKind::kOutsideValidity,
             fmt::format("the {} model is shear-rigid: the flexible segment's GAs = {:g} is not "
                         "modelled (shear adds about 3 EI/(GAs L^2) = {:.3g} of a cantilever's "
                         "bending tip deflection); the shooting method models it",
                         model_name(),
                         prepared.GAs,
                         3.0 * prepared.EI / (prepared.GAs * prepared.L * prepared.L)));
  }
  // The BCM alone (one element) is used beyond its range only with a warning; a chain of them is
  // judged by its measured error against N (docs/models.md), not by each element's deflection.
  if (out.converged() && !out.inside_validity && n == 1) {
    out.warn(WarningKind::kOutsideValidity,
             fmt::format("the BCM element deflects {:.3g} of its length, beyond its stated range "
                         "of about 0.1 (Awtar et al. 2007); the chained BCM (cbcm) follows larger "
                         "deflections",
                         out.max_element_deflection));
  }
  return out;
}

}  // namespace flexure
