#pragma once
// Inverse dynamics of the slider mechanism under a prescribed sinusoidal slider motion (the
// paper's test: "sinusoidal position input with amplitude equal to the full 40 % designed
// deflection with a slight pre-displacement to give a preload at full expansion"):
//   Delta x(t) = preload + stroke (1 - cos omega t)/2,
// and the input force F(t) of the whole mechanism from the equation of motion
//   M theta2'' + 1/2 M' theta2'^2 + V' = -F r1' + Q_CF + Q_AF          (docs/dynamics.md eq. D7)
// Frequency sweeps give per omega the mean, median, peak-to-peak force and the percent constant
// force 100 min F/max F (paper, PCF expression after Table 10) over one period.
#include <cstddef>
#include <functional>
#include <vector>

#include "flexure/mechanisms/dynamics/slider_crank_dynamics.h"

namespace flexure::dynamics {

struct SinusoidalMotion {
  double preload = 0.0;  // Delta x at full expansion, m (> 0: keeps theta2 > 0, where F is finite)
  double stroke = 0.0;   // peak-to-peak slider travel, m (> 0)
  double omega = 0.0;    // rad/s (>= 0)
};

struct ForceSample {
  double t = 0.0;             // s
  double delta_x = 0.0;       // slider displacement, m
  double theta2 = 0.0;        // rad
  double theta2_dot = 0.0;    // rad/s
  double theta2_ddot = 0.0;   // rad/s^2
  double force = 0.0;         // input force of the whole mechanism, N
  double static_force = 0.0;  // quasi-static force at the same Delta x, N
};

struct ForceStatistics {
  double omega = 0.0;
  double mean = 0.0;                    // time average over one period, N
  double median = 0.0;                  // N
  double min = 0.0;                     // N
  double max = 0.0;                     // N
  double peak_to_peak = 0.0;            // max - min, N
  double percent_constant_force = 0.0;  // 100 min/max (meaningful for min > 0)
};

struct InverseDynamicsOptions {
  int samples_per_period = 1024;        // uniform time samples over one period (>= 8, even so that
                                        // both ends of the stroke are sampled)
  double friction_sign_velocity = 0.0;  // > 0: sign(theta2') smoothed as tanh(theta2'/v), rad/s;
                                        // 0: exact sign (the force jumps at the stroke ends)

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

class InverseDynamics {
 public:
  // Throws InvalidInput if samples_per_period is odd or < 8.
  InverseDynamics(SliderCrankDynamics model, InverseDynamicsOptions options = {});

  // Force at time t. Throws InvalidInput for preload <= 0, stroke <= 0, omega < 0, or a stroke
  // that passes the toggle position.
  ForceSample at(const SinusoidalMotion& motion, double t) const;
  // One period (t_k = k T/N, k = 0..N-1); with omega = 0 the stroke is swept quasi-statically.
  std::vector<ForceSample> history(const SinusoidalMotion& motion) const;
  ForceStatistics statistics(const SinusoidalMotion& motion) const;
  // One statistics row per frequency. `progress(done, total)`, if set, is called after each row
  // (for a progress display on long sweeps).
  std::vector<ForceStatistics> sweep(
      SinusoidalMotion motion,
      const std::vector<double>& omegas,
      const std::function<void(std::size_t done, std::size_t total)>& progress = {}) const;

  const SliderCrankDynamics& model() const { return model_; }

 private:
  void check(const SinusoidalMotion& motion) const;
  ForceSample evaluate(double t, double delta_x, double x_dot, double x_ddot) const;

  SliderCrankDynamics model_;
  InverseDynamicsOptions options_;
};

// Mean of the quasi-static force of the whole mechanism over N equally spaced Delta x in
// (0, stroke] (Howell §10.1 sampling); with stroke = 40 % of r2 + r3 this is Table 6's F_Nom.
double static_nominal_force(const SliderCrankDynamics& model, double stroke, int points = 1000);

}  // namespace flexure::dynamics
