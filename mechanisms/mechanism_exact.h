#pragma once
// Exact (elastica) model of the half constant-force mechanism: the physical segments of thesis
// Table 8.1 as a SegmentChain clamped at the ground, solved with the shooting solver at each slider
// position, each point starting from the previous one (Newton from the neighbouring solution).
//
// Which configurations have an exact model (docs/mechanisms.md "Exact model"):
//  * kDirectChain (ssp, slp, sss): every intermediate joint is a flexure, so the half-mechanism is
//    one serial chain from the ground clamp to the slider; the slider end is `pinned` (x = slider
//    position, y = 0, M = 0) for a pin at the slider and `fixed` (theta = 0 as well) for a flexure
//    clamped into the slider. The input force is the x reaction at the slider.
//  * kTwoForceCoupler (spp, lpp): a rigid coupler between two pins carries only a force along
//    itself. The chain is the crank alone, pivot 2 lies on the circle of radius r3 about the
//    slider at coupler angle phi. Solved force-controlled: the crank is a cantilever under the
//    dead coupler force Q along the coupler, and Newton on (Q, phi) puts its tip on pivot 2 (see
//    solve_two_force; prescribing the tip instead is ill-conditioned near full extension).
//  * kPinnedMiddle (sps, lps): a pin at pivot 2 between the crank (clamped at the ground) and the
//    coupler (clamped into the slider by its flexure). Two cantilevers -- the crank from the ground
//    clamp, the coupler from the slider clamp (its own frame turned by pi) -- each carry the pin
//    force P as a dead tip load with zero tip moment. One Newton iteration on P, both root
//    moments (and any multiple-shooting cut states) makes both tip moments vanish and the tips
//    meet (solve_pinned_middle; the Jacobian comes from the integrator's sensitivities). Newton on
//    P alone around two separate cantilever solves fails where a cantilever carries about its
//    own buckling load, which is where these constant-force mechanisms work (docs/mechanisms.md
//    "Pinned middle").
//  * kPinnedEnds (psp, plp): pins at the ground and at the slider, so the half mechanism is a
//    pinned-pinned two-force member loaded along the slider axis. The chain starts with a root
//    kink alpha (the unknown crank angle) and carries the dead tip force (-F, 0); Newton on
//    (F, alpha) puts the tip on the slider joint (x_s, 0), which also makes the root moment
//    F y_tip vanish (the ground pin).
//  * kPrbmOnly: none of the nine configurations (kept for designs the model cannot represent).
//    Modelling a pin as a very compliant flexure would make the shooting problem ill-conditioned
//    (theta' = m/EI with EI -> 0) and add a spurious spring, so it is not done.
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure::mechanism {

// The physical chain (dimensional): from the ground clamp to the slider (kDirectChain) or to
// pivot 2 (kTwoForceCoupler, kPinnedMiddle, which adds coupler_chain); from the ground pin, with a
// zero-length root kink for the crank angle, to the slider (kPinnedEnds). `flexible_pivot[j]` =
// pivot (1..3) of segment j, 0 for a rigid link. Throws InvalidInput for kPrbmOnly.
struct PhysicalChain {
  SegmentChain chain;
  std::vector<int> flexible_pivot;
  double slider_x0 = 0.0;  // undeflected slider position (x of the slider joint), m
  // kPinnedMiddle: the coupler from the slider clamp to pivot 2, in a frame turned by pi about the
  // undeflected slider (root at the slider, +x towards the ground).
  SegmentChain coupler_chain;
  std::vector<int> coupler_flexible_pivot;
};
PhysicalChain physical_chain(const MechanismDesign& design);

class ExactMechanismSolver {
 public:
  // The settings (mechanism_analysis.h).
  using Options = ExactMechanismOptions;

  explicit ExactMechanismSolver(MechanismDesign design);
  ExactMechanismSolver(MechanismDesign design, Options options);

  // Solves at `displacement`, starting from `previous` if given (else from the PRBM state). With
  // `fall_back` false and a converged `previous`, the serial chain tries Newton from `previous`
  // only (no PRBM start, no continuation from zero load): what exact_stroke tries before it
  // divides a stroke step into substeps.
  ExactPoint solve(double displacement,
                   const ExactPoint* previous = nullptr,
                   bool fall_back = true) const;

  const MechanismDesign& design() const { return design_; }
  ExactSupport support() const { return support_; }
  // Past the work budget of options_?
  bool out_of_time() const;
  // Adds integrator steps to the stroke's work (no-op without a budget).
  void charge(long steps) const;
  // The message of a solve stopped by the work budget.
  std::string budget_message() const;
  // Largest nondimensional force magnitude within options_.max_load_parameter on every flexible
  // segment of the scaled chains (infinite when there is none).
  double max_force() const { return max_force_; }
  // The nondimensional chain solved at `displacement` (kDirectChain: with its slider end
  // condition) and the scales: force = nondimensional force * force_scale() N.
  SegmentChain scaled_chain(double displacement) const { return chain_at(displacement, 0.0); }
  double force_scale() const { return force_scale_; }
  const Options& options() const { return options_; }

 private:
  ExactPoint solve_direct(double displacement, const ExactPoint* previous, bool fall_back) const;
  ExactPoint solve_two_force(double displacement, const ExactPoint* previous) const;
  ExactPoint solve_pinned_middle(double displacement, const ExactPoint* previous) const;
  ExactPoint solve_pinned_ends(double displacement, const ExactPoint* previous) const;
  SegmentChain chain_at(double displacement, double phi) const;

  MechanismDesign design_;
  Options options_;
  ExactSupport support_;
  PhysicalChain physical_;       // dimensional
  SegmentChain scaled_;          // physical_.chain / (length_scale, EI_scale)
  SegmentChain scaled_coupler_;  // physical_.coupler_chain, scaled the same way
  double length_scale_ = 1.0, EI_scale_ = 1.0, force_scale_ = 1.0, moment_scale_ = 1.0;
  double max_force_ = INFINITY;  // see max_force()
};

// work_budget + work_budget_per_point * points.
double exact_work_limit(const ExactMechanismSolver::Options& options, std::size_t points);

// The stable stroke of a serial chain (mechanism_exact_stable.cpp): starts from the PRBM start
// when its first point is stable with the slider held, else on the branch of the straight chain's
// lowest buckling mode (exact_lowest_mode_point), and marches over a fixed grid of 128 equal
// steps plus `displacements`, judging each station where the shooting Jacobian's sign changes and
// taking the stable neighbour (exact_stable_neighbour) where the branch turns unstable; so the
// branch followed does not depend on the point count. Converged only when every station was
// followed; what was done is in stable_search.
ExactStrokeResult exact_stable_stroke(const MechanismDesign& design,
                                      const std::vector<double>& displacements,
                                      const ExactMechanismSolver::Options& options,
                                      const StrokeProgress& progress = nullptr);

// First point of a stroke when the PRBM start fails (mechanism_exact_start.cpp): near the straight
// position the PRBM force of a mechanism with long or very unequal flexures can lie below the exact
// buckling load (the shooting then finds the straight cantilever) or far enough off for Newton to
// diverge. Tries (1) the last stroke point from the PRBM start, walked back to the first in
// substeps; (2) a homotopy in the flexure thicknesses from all equal to the largest (a well
// conditioned chain) to the real ones at the first displacement. Length and EI scales stay those of
// the design, so the unknowns carry over. Returns the point at displacements[0] (converged = false
// with a message if both fail).
ExactPoint exact_first_point(const MechanismDesign& design,
                             const std::vector<double>& displacements,
                             const ExactMechanismSolver::Options& options);

// The straight serial chain (kDirectChain) at the undeflected slider position: its lowest buckling
// load under the slider's end condition (pinned or fixed, the chain's x held) and the root loads
// of its mode (mechanism_exact_start.cpp). The mechanism's stroke starts at this bifurcation: as
// the slider moves in, the straight chain buckles in its first mode, and the branch that leaves
// it is the stable one (docs/stability.md "Mechanisms"). The PRBM knows one mode only, the
// linkage turning about its pivots; a thin flexure between two long links can have a lower one
// of its own (3A-lssm: the middle strip sways at 10.1 N, the linkage mode needs 20.95 N).
struct ExactBucklingMode : SolveStatus {
  double load = 0.0;  // the lowest buckling load: the compressive force along the chain, N
  // The mode's root loads, nondimensional (ExactMechanismSolver::force_scale()), unit norm; the
  // sign turns the ground flexure the way the PRBM's crank turns (theta2 > 0).
  double m0 = 0.0, Ny = 0.0;
  double next_load = 0.0;  // the next buckling load found below the scanned bound (0: none), N
};
ExactBucklingMode exact_lowest_buckling_mode(const MechanismDesign& design,
                                             const ExactMechanismSolver::Options& options = {},
                                             double max_load = 0.0);

// The point at `displacement` on the branch that leaves the straight serial chain at its lowest
// buckling load: Newton from the mode at a small slider displacement (amplitude from the mode's
// end shortening), then walked to `displacement` in geometric steps. What exact_stroke uses when
// its first point is unstable with the slider held (mechanism_exact_start.cpp).
ExactPoint exact_lowest_mode_point(const MechanismDesign& design,
                                   double displacement,
                                   const ExactMechanismSolver::Options& options);

// Walks a serial chain's branch from the converged point `from` to the displacement `to` in steps
// that start at `first_step`, double after a converged step and halve after a failed one; a step
// across which the shooting Jacobian changes sign (a fold or bifurcation) is replaced by
// exact_stable_neighbour. `steps` (if given) gets the number of solves added.
ExactPoint exact_adaptive_walk(const MechanismDesign& design,
                               const ExactPoint& from,
                               double to,
                               double first_step,
                               const ExactMechanismSolver::Options& options,
                               int* steps = nullptr);

// A displacement-control-stable equilibrium at `displacement` next to the converged serial-chain
// point `from` whose branch lost its stability before `displacement` (a pitchfork: 3A-lslm's sway
// branch, where the symmetric states turn unstable and two mirror-image asymmetric ones take
// over): Newton from `from` displaced along the null direction of its shooting Jacobian, both
// ways, at growing amplitudes; the first stable result (mechanism_exact_start.cpp).
ExactPoint exact_stable_neighbour(const MechanismDesign& design,
                                  const ExactPoint& from,
                                  double displacement,
                                  const ExactMechanismSolver::Options& options);

// Bending moment, strain energy, stress and rotation of the flexible segments of a solved point
// (mechanism_exact_segments.cpp).
struct ExactSegmentState {
  std::array<double, 3> max_stress{};  // per pivot, Pa: max |m| h/(2I) + |N|/A
  double strain_energy = 0.0;          // J, integral of m^2/(2 EI) over the flexible segments
  std::array<double, 3> pivot_strain_energy{};  // J, the same per pivot
  // End-to-end rotation theta(end) - theta(start) of each pivot's flexible segment(s), rad; with
  // pivot_strain_energy it gives the energy-equivalent spring 2U/rotation^2 (modified_springs.h).
  std::array<double, 3> pivot_rotation{};
  std::array<bool, 3> has_pivot{};  // a flexible segment of this pivot was found
};
// From one integration of the point's solution, no Newton iteration and no sampled shape
// (solver/shooting/segment_moments.h): max |m| and the energy are as accurate as the integrated
// state (rtol of `options`, an explicit Runge-Kutta backend: rk8pd unless dormand-prince is
// asked for). What `mechanism analyze` reports for every stroke point.
ExactSegmentState exact_segment_state(
    const MechanismDesign& design,
    const ExactPoint& point,
    const ShootingSolver::Options& options = ExactMechanismSolver::Options{}.shooting);
// From the shape re-solved and sampled at `shape_points` equally spaced arc lengths:
// m(s) = m0 + Nx y(s) - Ny x(s) (statics of the distal part, no node loads); max |m| over the
// samples, strain energy by the trapezoidal rule on each flexible segment (end values
// interpolated). An independent check of the above (and of exact_strain_energy's quadrature).
ExactSegmentState exact_segment_state(const MechanismDesign& design,
                                      const ExactPoint& point,
                                      int shape_points);

// Strain energy of a solved point, J, to quadrature accuracy far below the solver's: the
// trapezoidal value of exact_segment_state at n and 2n - 1 shape samples, Richardson-extrapolated
// (its error and the linear interpolation of the segment ends are both O(h^2) on a smooth shape),
// (4 U(h/2) - U(h))/3. Measured: the energy balance over the stroke then closes to 2e-11-6e-10
// on the built-in designs (docs/mechanisms.md), where U(h) alone at n = 8001 left 6e-7 on the
// short s flexures of 3A-sss.
double exact_strain_energy(const MechanismDesign& design,
                           const ExactPoint& point,
                           int shape_points = 8001);

// Second opinion: Howell's chain algorithm (N elements over the flexible segments of a chain) on
// the solved exact point, for every topology (mechanism_exact_chain_check.cpp). Each flexible
// segment of each chain (crank chain, serial chain to the slider, coupler chain of a middle pin) is
// cut into parts short enough that their equilibrium under dead loads is unique; each part is
// clamped at its solved root pose and loaded at its tip by the solved internal force and moment;
// the parts' tips, composed root to tip with the rigid links, give the chain's tip, compared with
// the shooting tip. (The whole chain under its dead end loads is not a usable check: the chain
// algorithm's proportional loading from the straight chain finds another equilibrium of the
// post-buckled, neutrally stable constant-force mechanism; a prescribed slider end starts it at a
// bifurcation.)
struct ChainCheck : SolveStatus {
  double force = 0.0;        // slider force of the shooting solution, N
  double tip_error = 0.0;    // largest |tip_chain - tip_shooting| over the chains, m
  double angle_error = 0.0;  // largest |theta_chain - theta_shooting| at a chain tip, rad
  // How far the chain-algorithm tips miss the joint the mechanism closes on, m: the slider joint
  // (serial chain, pinned ends), each other (crank and coupler at the middle pin), the line of
  // the coupler force through the slider joint (two-force coupler). Includes the shooting
  // solution's own closure residual.
  double closure_error = 0.0;
  int pieces = 0;  // flexible parts solved by the chain algorithm
};
ChainCheck chain_algorithm_check(const ExactPoint& point, int elements);  // corrected variant
ChainCheck chain_algorithm_check(const ExactPoint& point, int elements, ChainVariant variant);

}  // namespace flexure::mechanism
