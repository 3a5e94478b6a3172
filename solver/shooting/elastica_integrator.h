#pragma once
// Arc-length integration of a segment chain with forward sensitivities: GSL's Prince-Dormand 8(7)
// (the default), SUNDIALS CVODES (the reference) or the built-in Dormand-Prince 5(4).
//
// State along the chain: (x, y, theta, m), m the bending moment (convention of
// solver/chain_model/segment_chain.h). On a flexible segment (Howell eqs. 2.67-2.69 in
// differential form):
//     x' = cos theta,  y' = sin theta,  theta' = m / EI(s) + kappa0,
//     m' = N_x sin theta - N_y cos theta       (N the internal force, constant on the segment).
// A rigid segment is crossed analytically (a straight link), and at node k the moment drops by the
// node's dead moment. The caller supplies the internal force on every segment and the moment
// drops, so the integrator knows nothing about which loads are unknown.
//
// Sensitivities: each parameter p declares d m(0)/dp, dN/dp on every segment and d(moment
// drop)/dp at every node; S' = J S + df/dp is integrated alongside the state (CVODES: staggered
// off, simultaneous corrector; the explicit backends: one packed system with the error test on
// all of it), which gives the exact Jacobian of the tip state for the Newton solver.
#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

// Internal loads along the chain for one evaluation.
struct ChainForces {
  double m0 = 0.0;  // bending moment at the root, m(0)
  // Internal force at the near end of segment j (size n) from the dead loads: constant on the
  // segment without distributed loads; with them N(s) = N[j] - load_factor Q_j(s) - G(s), Q_j the
  // segment's dead-load resultant from its start and G the follower pressures' resultant from the
  // root, which the integrator accumulates (docs/distributed-loads.md).
  std::vector<Eigen::Vector2d> N;
  std::vector<double> moment_drop;  // m(after node k) = m(before) - moment_drop[k]; size n+1
  double load_factor = 0.0;         // the factor of the segments' distributed loads
};

// Derivatives of ChainForces with respect to one shooting parameter (the parameter's effect on
// the start state is given separately, as a column of the start sensitivity).
struct ForceDerivative {
  std::vector<Eigen::Vector2d> dN;   // size n (empty = all zero)
  std::vector<double> dmoment_drop;  // size n+1 (empty = all zero)
  double dload_factor = 0.0;         // d(ChainForces::load_factor)/dp
};

// A stretch of one segment integrated in one call: local arc lengths [begin, end] of segment
// `segment` (a rigid segment is always whole). `crosses_far_node` applies node segment+1's moment
// drop after the stretch.
struct IntegrationPiece {
  int segment = 0;
  double begin = 0.0;  // local arc length on the segment
  double end = 0.0;
  double segment_start = 0.0;  // global arc length of the segment's near end
  bool crosses_far_node = false;
};

class StepObserver;  // elastica_piece.h

class ElasticaIntegrator {
 public:
  // The backends and the integrator's settings (shooting_solver.h: IntegratorBackend,
  // IntegratorOptions), under their old names.
  using Backend = IntegratorBackend;
  using Options = IntegratorOptions;
  explicit ElasticaIntegrator(Options options);
  ~ElasticaIntegrator();
  ElasticaIntegrator(const ElasticaIntegrator&) = delete;
  ElasticaIntegrator& operator=(const ElasticaIntegrator&) = delete;

  // Integrates the consecutive `pieces` from the state `start` = (x, y, theta, m) with start
  // sensitivities `start_sensitivity` (4 x Ns; Ns = derivatives.size(), may be 0). When `shape` is
  // not null, the pose at the arc lengths `shape_s` (ascending) that fall inside the pieces is
  // appended (all remaining ones when `last` is true). Returns false and sets `error` when CVODES
  // fails (the flag is named) or the state is not finite.
  bool integrate(const SegmentChain& chain,
                 const std::vector<IntegrationPiece>& pieces,
                 const ChainForces& forces,
                 const std::vector<ForceDerivative>& derivatives,
                 const Eigen::Vector4d& start,
                 const Eigen::Matrix<double, 4, Eigen::Dynamic>& start_sensitivity,
                 TipState& end,
                 std::string& error,
                 const std::vector<double>* shape_s = nullptr,
                 std::vector<ShapePoint>* shape = nullptr,
                 bool last = true);

  // Every accepted step of the following integrations is shown to `observer` (null: none). Only
  // the explicit Runge-Kutta backends (kRk8pd, kDormandPrince) have steps to show; with another
  // backend integrate() fails saying so.
  void set_step_observer(StepObserver* observer) { observer_ = observer; }
  // > 0: integrate() fails ("step limit reached") once steps_taken() would exceed this total; the
  // explicit backends stop within a step, CVODES at the next piece. 0: no limit (the default).
  // Newton uses it to give up on a trial point that costs far more than the current one
  // (NewtonOptions::trial_cost_factor).
  void set_step_limit(long total_steps) { step_limit_ = total_steps; }
  // Not null: every shape point integrate() appends also appends its bending moment m here (the
  // integrated state; with distributed loads the statics of the shape cannot give it exactly).
  void set_shape_moments(std::vector<double>* moments) { shape_moment_ = moments; }

  const Options& options() const { return options_; }
  long steps_taken() const;  // integrator steps since construction (work budgets, performance)

 private:
  bool ensure_sensitivities(int Ns, std::string& error);
  struct Impl;
  Options options_;
  StepObserver* observer_ = nullptr;
  long step_limit_ = 0;
  std::vector<double>* shape_moment_ = nullptr;
  std::unique_ptr<Impl> impl_;
};

}  // namespace flexure
