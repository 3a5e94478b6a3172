#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "flexure/elements/chained_bcm_model.h"
#include "flexure/elements/ladder_models.h"
#include "flexure/elements/load_path_newton.h"
#include "flexure/solver/chain_model/tip_reach.h"
#include "flexure/solver/common/status.h"

namespace flexure {

using namespace detail::cbcm;  // NOLINT: the model of chained_bcm_model.h

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
  const EndLoads loads = end_loads(prepared, e, lambda);
  out.reaction = {
      -loads.clamp.Fx * force_unit, -loads.clamp.Fy * force_unit, -loads.clamp.M * moment_unit};
  out.root_moment = loads.clamp.M * moment_unit;
  out.tip_load = {loads.tip.Fx * force_unit, loads.tip.Fy * force_unit, loads.tip.M * moment_unit};
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
