#pragma once
// Forward dynamics of the slider mechanism with the beam layer's ODE integrator
// (solver/ode/ode_integrator.h, SUNDIALS CVODES): the equation of motion
//   M(theta2) theta2'' = -1/2 M'(theta2) theta2'^2 - V'(theta2) - F r1'(theta2) + Q_CF
// (docs/dynamics.md eq. D7) as a first-order system in (theta2, theta2'), driven by an input force
// F(t, theta2, theta2') of the whole mechanism (a prescribed force, a driving spring, or zero for a
// release). Coulomb friction is smoothed as tanh(theta2'/v) so that the right-hand side stays
// continuous; the axial-force term of eq. 28 is not used here (it is a force-measurement
// correction, not a physical moment).
#include <functional>
#include <string>
#include <vector>

#include "flexure/mechanisms/dynamics/slider_crank_dynamics.h"
#include "flexure/solver/common/status.h"

namespace flexure::dynamics {

// Input force of the whole mechanism, N (F > 0 compresses).
using InputForce = std::function<double(double t, double theta2, double theta2_dot)>;

// A linear driving spring of stiffness k_drive (N/m) between an actuator at slider displacement
// actuator(t) (m) and the slider: F = k_drive (actuator(t) - Delta x(theta2)), the force of the
// whole mechanism (a load cell in series with a crank-driven block, paper Fig. 7).
InputForce driving_spring(const SliderCrankDynamics& model,
                          double k_drive,
                          std::function<double(double t)> actuator);

struct ForwardOptions {
  double rtol = 1e-10;                   // CVODES relative tolerance
  double atol = 1e-14;                   // CVODES absolute tolerance on theta2 and theta2'
  long max_steps = 1000000;              // steps allowed between two output times
  bool adams = true;                     // Adams-Moulton (non-stiff) or BDF
  double friction_sign_velocity = 1e-3;  // tanh smoothing of sign(theta2'), rad/s (> 0)
  // When true, times where theta2 crosses `crossing_level` upward are recorded (an event of the
  // ODE integrator, CVODES root finding), e.g. for periods of free oscillations.
  bool record_crossings = false;
  double crossing_level = 0.0;  // rad

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

struct ForwardResult : SolveStatus {
  std::vector<double> t;                 // output times, s
  std::vector<double> theta2;            // rad
  std::vector<double> theta2_dot;        // rad/s
  std::vector<double> delta_x;           // slider displacement, m
  std::vector<double> energy;            // kinetic + spring energy, J
  std::vector<double> upward_crossings;  // times of upward crossings of crossing_level, s
  // iterations: CVODES steps
  // residual: largest |energy - energy(0)|/energy(0) when the force is zero
};

// Linearised small-oscillation frequency about the equilibrium under a constant force F0 (whole
// mechanism, N): theta* solves V'(theta) + F0 r1'(theta) = 0 and
//   omega_n^2 = (V''(theta*) + F0 r1''(theta*))/M(theta*).
struct Linearisation {
  double theta2_eq = 0.0;  // equilibrium crank angle, rad
  double stiffness = 0.0;  // V'' + F0 r1'', N m/rad
  double inertia = 0.0;    // M(theta*), kg m^2
  double omega_n = 0.0;    // rad/s (0 if the stiffness is not positive)
  bool stable = false;     // stiffness > 0
};
// With F0 = 0 the equilibrium is theta2 = 0 (straight); for F0 > 0 it is searched by bisection on
// [theta_lo, theta_hi] (default: (0, toggle)). A constant-force mechanism's static force can equal
// F0 at several angles, so pass a bracket around the wanted one. Throws InvalidInput if F0 < 0 or
// the static force does not cross F0 in the bracket.
Linearisation linearise(const SliderCrankDynamics& model,
                        double F0,
                        double theta_lo = 0.0,
                        double theta_hi = 0.0);

class ForwardDynamics {
 public:
  explicit ForwardDynamics(SliderCrankDynamics model, ForwardOptions options = {});

  // Integrates from (theta2_0, theta2_dot_0) at t = 0 and reports the state at each of
  // `output_times` (increasing, > 0). A null force means F = 0 (free motion).
  ForwardResult integrate(double theta2_0,
                          double theta2_dot_0,
                          const std::vector<double>& output_times,
                          const InputForce& force) const;

  const SliderCrankDynamics& model() const { return model_; }

 private:
  SliderCrankDynamics model_;
  ForwardOptions options_;
};

}  // namespace flexure::dynamics
