#include "flexure/benchmarks/studies/bench_solve.h"

#include <fmt/format.h>

#include <algorithm>
#include <exception>

#include "flexure/elements/prbm_cantilever.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure::bench {
namespace {

SegmentChain make_chain(const BenchProblem& problem, const LoadPoint& load) {
  SegmentChain chain = uniform_cantilever(EndLoad::howell(load.load_ratio_n, load.alpha2, load.mu));
  chain.end = problem.boundary;
  return chain;
}

// The cantilever's PRBM element for the end and the load (elements/prbm_cantilever.h), as
// `flexure beam --method prbm` and `--method auto` use it.
PointSolution solve_prbm(const BenchProblem& problem, const LoadPoint& load) {
  const PrbmCantileverSolution eq =
      solve_prbm_cantilever(problem.boundary, load.load_ratio_n, load.alpha2, load.mu);
  PointSolution out;
  out.status = eq.converged() ? kStatusConverged : kStatusNotConverged;
  out.tip = eq.tip;
  out.iterations = eq.iterations;
  out.message = eq.converged() ? "" : eq.message;
  // Howell eq. 5.47 (position) and eq. 5.63 (force): the constants are trusted below both.
  out.inside_validity = eq.inside_validity ? 1 : 0;
  return out;
}

}  // namespace

CfmStrokeSolver::CfmStrokeSolver(const std::string& mechanism)
    : exact_(mechanism::find_builtin_mechanism(mechanism)) {}

PointSolution CfmStrokeSolver::solve(MethodFamily family, double displacement) {
  PointSolution out;
  try {
    if (family == MethodFamily::kPrbm) {
      const mechanism::PrbmState state = mechanism::prbm_state(exact_.design(), displacement);
      require_finite(state.force, "PRBM slider force");
      out.status = kStatusConverged;
      out.force = state.force;
      out.iterations = 0;  // closed form (thesis eq. 2.14)
      return out;
    }
    if (family != MethodFamily::kMechanismExact) {
      throw InvalidInput(fmt::format(
          "method family '{}' has no mechanism model (use prbm or exact)", to_string(family)));
    }
    mechanism::ExactPoint p = exact_.solve(displacement, previous_ ? &previous_.value() : nullptr);
    out.status = p.converged() ? kStatusConverged : kStatusNotConverged;
    out.force = p.force;
    out.iterations = p.iterations;
    if (!p.converged()) {
      out.message = p.message;
      last_.reset();
    } else {
      last_ = std::move(p);
    }
  } catch (const std::exception& e) {
    out = PointSolution{};
    out.status = kStatusError;
    out.message = e.what();
    last_.reset();
  }
  return out;
}

void CfmStrokeSolver::accept_last() {
  if (last_) previous_ = last_;
}

BenchMethod reference_shooting_method() {
  BenchMethod m;
  m.name = "shooting_cvodes_rtol1e-12";
  m.family = MethodFamily::kShooting;
  m.backend = ElasticaIntegrator::Backend::kCvodes;
  m.rtol = 1e-12;
  return m;
}

PointSolution solve_point(const BenchMethod& method,
                          const BenchProblem& problem,
                          const LoadPoint& load) {
  PointSolution out;
  try {
    switch (method.family) {
      case MethodFamily::kElliptic: {
        const EllipticResult r =
            EllipticSolver().solve(EndLoad::howell(load.load_ratio_n, load.alpha2, load.mu));
        out.status = r.converged() ? kStatusConverged : kStatusNotConverged;
        out.tip = r.tip;
        out.iterations = r.iterations;
        if (!r.converged()) out.message = r.message;
        break;
      }
      case MethodFamily::kShooting: {
        ShootingSolver::Options options;
        options.backend = method.backend;
        options.rtol = method.rtol;
        // atol two decades below rtol, as the reference (1e-12, 1e-14).
        options.atol = method.rtol * 1e-2;
        const ShootingResult r = solve_shooting(make_chain(problem, load), options);
        out.status = r.converged() ? kStatusConverged : kStatusNotConverged;
        out.tip = r.tip_pose(1.0);
        out.iterations = r.iterations;
        if (!r.converged()) out.message = r.message;
        break;
      }
      case MethodFamily::kChain: {
        ChainAlgorithmSolver::Options options;
        options.elements = method.elements;
        options.increments = method.increments;
        options.record_load_path = false;
        // The study measures this N: a load it cannot represent is a failure of that N, not a
        // reason to solve with another.
        options.refine_elements = false;
        const ChainResult r = solve_chain(make_chain(problem, load), options);
        out.status = r.converged() ? kStatusConverged : kStatusNotConverged;
        out.tip = r.tip_pose;
        out.iterations = r.iterations;
        if (!r.converged()) out.message = r.message;
        break;
      }
      case MethodFamily::kPrbm:
        out = solve_prbm(problem, load);
        break;
      case MethodFamily::kMechanismExact:
        throw InvalidInput("the exact mechanism model solves mechanism problems only");
    }
  } catch (const std::exception& e) {
    out = PointSolution{};
    out.status = kStatusError;
    out.message = e.what();
  }
  return out;
}

}  // namespace flexure::bench
