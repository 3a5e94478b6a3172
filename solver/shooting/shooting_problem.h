#pragma once
// The shooting residual of a segment chain: unknown root loads -> far-end conditions, with
// multiple shooting for large loads.
//
// Root unknowns (Howell eq. 7.37 with the reaction loads as the guessed vector):
//   z[0] = m(0), the bending moment at the root (always unknown);
//   N_x(0) if the tip x is prescribed or a follower force acts; N_y(0) likewise.
// Dead loads make the internal force piecewise constant and known, so a component that is neither
// conjugate to a prescribed coordinate nor affected by a follower is not shot for. A follower force
// depends on theta(tip), so both force components become unknowns with a force-balance residual.
//
// Multiple shooting: under an internal force N the linearised elastica grows like
// exp(s sqrt(|N|/EI)) (the hyperbolic branch of the pendulum), so single shooting loses digits and
// jumps between equilibria for large loads. Flexible segments are therefore cut into parts of
// length <= budget * sqrt(EI/|N|); the state (x, y, theta, m) at every interior cut is an extra
// unknown and continuity at the cut an extra residual.
//
// Residuals g(z, lambda), in this order (lambda the proportional load factor):
//   theta: theta(tip) - theta*(lambda) if prescribed, else m(tip) - lambda M_tip;
//   x    : x(tip) - x*(lambda) if prescribed, else N_x(tip) - lambda F_x,tip(theta_tip);
//   y    : y(tip) - y*(lambda) if prescribed, else N_y(tip) - lambda F_y,tip(theta_tip);
//   then 4 continuity residuals per interior cut: state at the end of an interval minus the
//   unknown state at the start of the next.
// The Jacobian dg/dz and dg/dlambda come from CVODES forward sensitivities (no finite differences).
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

struct ShootingEvaluation {
  bool ok = false;
  std::string error;  // CVODES failure, when !ok
  Eigen::VectorXd residual;
  Eigen::MatrixXd jacobian;  // dg/dz (when requested)
  Eigen::VectorXd d_lambda;  // dg/dlambda (when requested)
  TipState tip;              // state at the tip (sensitivities not mapped)
};

// How the load factor lambda enters the problem. Default: proportional loading from the
// stress-free chain (segment_chain.h). Loads are multiplied by load_offset + load_slope * lambda;
// each prescribed tip coordinate moves from tip_start (lambda = 0) to its target (lambda = 1).
// `mask` may release prescribed coordinates (their conjugate load is then the given one, zero),
// which the solver uses to reach a pinned end in two stages (shooting_solver.cpp), and may
// prescribe a coordinate the end condition leaves free (displacement control: its conjugate tip
// load, which must be given as zero, becomes the support's reaction).
struct Homotopy {
  double load_offset = 0.0;
  double load_slope = 1.0;
  std::optional<ChainPose> tip_start;   // default: the stress-free tip
  std::optional<ChainPose> tip_target;  // default: chain.prescribed_tip()
  std::optional<PrescribedMask> mask;   // default: prescribed_mask(chain.end)
};

class ShootingProblem {
 public:
  // Validates the chain (throws InvalidInput). `chain` is the full-load problem (lambda = 1).
  explicit ShootingProblem(const SegmentChain& chain,
                           MultipleShootingOptions options = {},
                           Homotopy homotopy = {});

  int size() const { return static_cast<int>(unknown_names_.size()); }
  int root_unknown_count() const { return root_count_; }
  int interval_count() const { return static_cast<int>(intervals_.size()); }
  const std::vector<std::string>& unknown_names() const { return unknown_names_; }
  const SegmentChain& chain() const { return chain_; }

  // Internal loads for unknowns z at load factor lambda.
  ChainForces forces(const Eigen::VectorXd& z, double lambda) const;
  Reaction reaction(const Eigen::VectorXd& z, double lambda) const;

  bool evaluate(const Eigen::VectorXd& z,
                double lambda,
                bool want_jacobian,
                bool want_lambda_derivative,
                ElasticaIntegrator& integrator,
                ShootingEvaluation& out) const;

  double load_factor(double lambda) const {
    return homotopy_.load_offset + homotopy_.load_slope * lambda;
  }
  const PrescribedMask& mask() const { return mask_; }

  // The stress-free state (root unknowns 0, cut states on the unloaded chain) solves g(., 0) = 0
  // for the default homotopy.
  Eigen::VectorXd unloaded_unknowns() const;

  // Full unknown vector from root unknowns alone: the cut states are taken from one integration
  // from the root. Returns false (with `error`) when that integration fails.
  bool complete_guess(const Eigen::VectorXd& root_unknowns,
                      double lambda,
                      ElasticaIntegrator& integrator,
                      Eigen::VectorXd& z,
                      std::string& error) const;

  // Tip state and (optionally) the shape at arc lengths `s` for a solution z.
  bool integrate_solution(const Eigen::VectorXd& z,
                          double lambda,
                          ElasticaIntegrator& integrator,
                          TipState& tip,
                          std::string& error,
                          const std::vector<double>* s = nullptr,
                          std::vector<ShapePoint>* shape = nullptr) const;

 private:
  Eigen::Vector4d interval_start(const Eigen::VectorXd& z, int k) const;

  SegmentChain chain_;
  Homotopy homotopy_;
  PrescribedMask mask_;
  ChainPose tip_unloaded_;
  ChainPose tip_start_;
  ChainPose tip_target_;
  int index_Nx_ = -1;  // position of N_x(0) in z, or -1
  int index_Ny_ = -1;
  int root_count_ = 1;              // m0 plus shot force components
  Eigen::Vector2d node_force_sum_;  // sum of intermediate and distributed dead forces, full load
  std::vector<Eigen::Vector2d> segment_dead_load_;  // each segment's dead-load resultant
  Eigen::Vector2d tip_dead_force_;
  std::vector<std::vector<IntegrationPiece>> intervals_;
  std::vector<Eigen::Vector4d> unloaded_cut_states_;  // stress-free state at each interior cut
  std::vector<std::string> unknown_names_;
};

}  // namespace flexure
