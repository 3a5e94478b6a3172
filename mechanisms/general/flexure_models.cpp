#include <algorithm>
#include <cmath>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/ladder_selector.h"
#include "flexure/elements/ladder_models.h"
#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

FlexureTip from_pose(const TipPose& t) { return {t.a_over_l, t.b_over_l, t.theta0}; }

// The PRBM element as a cantilever under tip loads: one PRB link of length rho from the pivot at
// s_p (x/l) to the tip, a torsion spring K (EI/l) at the pivot. Equilibrium of the link about the
// pivot, K Theta = mu + rho (Fy cos Theta - Fx sin Theta), followed by Newton over 20 equal steps
// of proportional loading from Theta = 0 (the branch a mechanism starts on).
bool prbm_element_tip(PrbmKind kind,
                      const FlexureTipLoad& load,
                      FlexureTip& tip,
                      std::string* why) {
  double s_p = 0.0, rho = 0.0, K = 0.0;
  if (kind == PrbmKind::kSmallLengthPivot) {
    const SmallLengthFlexuralPivot element(0.0);  // Howell §5.1: pivot at l/2, K = EI/l
    s_p = element.geometry().pivot_x;
    rho = element.geometry().link_length;
    K = element.stiffness_coefficient();
  } else if (kind == PrbmKind::kFixedPinned) {
    const FixedPinnedSegment& element = howell_average_fixed_pinned();  // Howell §5.2, eq. 5.72
    s_p = element.geometry().pivot_x;
    rho = element.geometry().link_length;
    K = element.stiffness_coefficient();
  } else {
    if (why != nullptr) {
      *why =
          "the fixed-guided PRBM element has two pivots and is not a cantilever under tip loads; "
          "choose exact, linear, bcm, prbm3r, cbcm or chain for it (or --model prbm for every "
          "flexure)";
    }
    return false;
  }
  double Theta = 0.0;
  constexpr int kSteps = 20;
  for (int step = 1; step <= kSteps; ++step) {
    const double lambda = static_cast<double>(step) / kSteps;
    bool done = false;
    for (int it = 0; it < 50; ++it) {
      const double c = std::cos(Theta), s = std::sin(Theta);
      const double g = K * Theta - lambda * (load.mu + rho * (load.Fy * c - load.Fx * s));
      const double dg = K + lambda * rho * (load.Fy * s + load.Fx * c);
      if (std::fabs(g) < 1e-14 * (1.0 + K * std::fabs(Theta))) {
        done = true;
        break;
      }
      if (!(dg > 0.0)) {
        break;  // past the element's own buckling load: no stable answer on this path
      }
      Theta -= g / dg;
    }
    if (!done) {
      if (why != nullptr) {
        *why =
            "its PRBM element has no equilibrium on the proportional load path (past its "
            "buckling load)";
      }
      return false;
    }
  }
  tip = {s_p + rho * std::cos(Theta), rho * std::sin(Theta), Theta};
  return true;
}

}  // namespace

const std::vector<FlexureModel>& auto_ladder() {
  static const std::vector<FlexureModel> ladder = {
      FlexureModel::kLinear, FlexureModel::kBcm, FlexureModel::kPrbm3r, FlexureModel::kCbcm};
  return ladder;
}

bool model_tip(FlexureModel model,
               PrbmKind prbm,
               int elements,
               const FlexureTipLoad& load,
               FlexureTip& tip,
               std::string* why) {
  if (!std::isfinite(load.Fx) || !std::isfinite(load.Fy) || !std::isfinite(load.mu)) {
    if (why != nullptr) *why = "a load that is not finite";
    return false;
  }
  CantileverCase c;
  c.load = EndLoad{load.Fx, load.Fy, load.mu};
  try {
    switch (model) {
      case FlexureModel::kPrbm:
        return prbm_element_tip(prbm, load, tip, why);
      case FlexureModel::kLinear:
        tip = from_pose(LinearBeamSolver().solve(c).tip);
        return true;
      case FlexureModel::kBcm: {
        const BcmResult r = BcmSolver().solve(c);
        if (!r.converged()) break;
        tip = from_pose(r.tip);
        return true;
      }
      case FlexureModel::kPrbm3r: {
        const Prbm3rResult r = Prbm3rSolver().solve(c);
        if (!r.converged()) break;
        tip = from_pose(r.tip);
        return true;
      }
      case FlexureModel::kCbcm: {
        ChainedBcmSolver::Options o;
        o.elements = elements;
        const CbcmResult r = ChainedBcmSolver(o).solve(c);
        if (!r.converged()) break;
        tip = from_pose(r.tip_pose());
        return true;
      }
      case FlexureModel::kChain: {
        // Howell's chain algorithm (§7.2) on the cantilever under the dead tip loads, followed
        // from the unloaded beam (the branch a mechanism starts on), as `flexure beam --method
        // chain`, but with exactly the N asked for: its self-check may not double the elements,
        // since a count that changed between two residuals of the mechanism's Newton system
        // would make the tip jump by the discretisation error.
        ChainAlgorithmSolver::Options o;
        o.elements = elements;
        o.refine_elements = false;
        o.record_load_path = false;
        const ChainResult r = ChainAlgorithmSolver(o).solve(c.load);
        if (!r.converged()) {
          if (why != nullptr) *why = "the chain algorithm did not converge: " + r.message;
          return false;
        }
        tip = from_pose(r.tip_pose);
        return true;
      }
      default:
        if (why != nullptr) *why = "not a model of one flexure under tip loads";
        return false;
    }
  } catch (const InvalidInput& e) {
    if (why != nullptr) *why = e.what();
    return false;
  }
  if (why != nullptr) {
    *why = std::string(flexure_model_name(model)) + " did not converge under these loads";
  }
  return false;
}

namespace {

// Howell's load parameters of a tip load, mirrored about the flexure's axis when the transverse
// force is negative (the map's alpha2 >= 0): false when there is no load ratio n (Fy = 0, Fx != 0).
bool howell_load(const FlexureTipLoad& load, double& n, double& alpha2, double& mu) {
  const double sign = load.Fy < 0.0 ? -1.0 : 1.0;
  alpha2 = std::fabs(load.Fy);
  mu = sign * load.mu;
  if (alpha2 == 0.0) {
    if (load.Fx != 0.0) return false;
    n = 0.0;
    return true;
  }
  n = -load.Fx / alpha2;
  return std::isfinite(n);
}

}  // namespace

bool exact_flexure_tip(const FlexureTipLoad& load, FlexureTip& tip) {
  // A load of round-off size (a flexure at rest in a mechanism: |F l^2/EI| ~ 1e-17 with any load
  // ratio) is linear theory's to its square; the elliptic solution there resolves only its own
  // tolerance (measured: 1.4e-6 of the length at Fx/Fy = 45, 1e-17).
  if (std::max({std::fabs(load.Fx), std::fabs(load.Fy), std::fabs(load.mu)}) < 1e-9) {
    tip = {1.0, load.Fy / 3.0 + load.mu / 2.0, load.Fy / 2.0 + load.mu};
    return true;
  }
  double n = 0.0, alpha2 = 0.0, mu = 0.0;
  if (!howell_load(load, n, alpha2, mu)) return false;
  BeamProblem p;
  p.given = BeamProblem::Given::kAlpha2;
  p.value = alpha2;
  p.load_ratio_n = n;
  p.mu = mu;
  p.judge_stability = false;
  try {
    const BeamSolution s = solve_beam(BeamMethod::kElliptic, p);
    if (!s.converged()) return false;
    const double sign = load.Fy < 0.0 ? -1.0 : 1.0;
    tip = {s.tip.a_over_l, sign * s.tip.b_over_l, sign * s.tip.theta0};
    return true;
  } catch (const InvalidInput&) {
    return false;
  } catch (const NoConvergence&) {
    return false;
  }
}

double measured_tip_error(const FlexureTipLoad& load, const FlexureTip& tip) {
  FlexureTip exact;
  if (!exact_flexure_tip(load, exact)) return kNaN;
  return std::hypot(tip.x - exact.x, tip.y - exact.y);
}

double mapped_flexure_error(FlexureModel model, int elements, const FlexureTipLoad& load) {
  if (model == FlexureModel::kExact) return 0.0;
  BeamMethod method;
  switch (model) {
    case FlexureModel::kLinear:
      method = BeamMethod::kLinear;
      break;
    case FlexureModel::kBcm:
      method = BeamMethod::kBcm;
      break;
    case FlexureModel::kPrbm3r:
      method = BeamMethod::kPrbm3r;  // the map's: Su's general constants
      break;
    case FlexureModel::kCbcm:
      if (elements != 6) return kNaN;  // the map's CBCM has 6 elements
      method = BeamMethod::kCbcm;
      break;
    default:
      // The PRBM element's average constants are not the map's 1R model; the chain algorithm
      // (any N) is not on the map.
      return kNaN;
  }
  double n = 0.0, alpha2 = 0.0, mu = 0.0;
  if (!howell_load(load, n, alpha2, mu)) return kNaN;
  return bench::ladder_mapped_error_any_n(method, n, alpha2, mu);
}

}  // namespace flexure::mechanism::general
