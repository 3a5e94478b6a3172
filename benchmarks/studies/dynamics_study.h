#pragma once
// `flexure dynamics` as a library function: the frequency sweep of the input force of a modified
// constant-force slider mechanism under the sinusoidal slider motion of the dynamics paper
// (Ugwuoke & Abolarin; docs/dynamics.md), with the static nominal force, the natural frequency of
// the unloaded mechanism and one period of the force history at chosen frequencies.
//
//   Delta x(t) = preload + stroke (1 - cos omega t)/2,   preload, stroke in % of r2 + r3.
//
// The model (mechanisms/dynamics) computes the whole symmetric mechanism: two halves and one
// slider. Every force of the study is reported as `force_of` says (mechanisms/mechanism.h: one
// half is exactly half of the whole, with the slider's inertia shared equally).
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct DynamicsStudyOptions {
  std::vector<double> omegas;            // drive frequencies, rad/s (>= 0, at least one)
  std::optional<double> stroke_percent;  // peak-to-peak travel, % of r2 + r3, in (0, 100]; unset:
                                         // the design's own stroke, else 40 % (paper Table 6)
  double preload_percent = 1.0;          // Delta x at full expansion, % of r2 + r3, in (0, 100]
  int samples = 1024;                    // time samples per period (even, >= 8)
  std::array<double, 3> friction{};      // Coulomb pin friction C1..C3 per half, N m (eq. 27)
  double axial_alpha = 0.0;              // angle of axial-force effect of eq. 28, rad (0: off)
  bool zero_slider_mass = false;         // the slider's mass set to zero
  bool zero_inertia = false;             // every mass and inertia set to zero
  std::vector<double> history_omegas{10.472, 31.416, 62.832};  // rad/s; paper Figs. 11-13
  mechanism::ForceOf force_of = mechanism::ForceOf::kWholeMechanism;
  // Samples of the static nominal force: the mean over Delta x = k stroke/N, k = 1..N, as
  // `mechanism analyze --points N` samples its stroke (dynamics.h static_nominal_force).
  int static_force_points = 1000;
  // Called after each frequency of the sweep with (done, total).
  std::function<void(std::size_t done, std::size_t total)> progress;

  // Throws InvalidInput naming the first field outside its range (the sample count is checked by
  // dynamics::InverseDynamicsOptions).
  void validate() const;
};

// The model parameters and the motion a study uses (motion.omega = 0).
struct DynamicsStudySetup {
  dynamics::DynamicsParameters parameters;
  dynamics::SinusoidalMotion motion;
};

// One period of the motion at one frequency; forces of the study's force_of.
struct DynamicsForceHistory {
  double omega = 0.0;
  std::vector<double> t, delta_x, theta2, force, static_force;
};

struct DynamicsStudy : SolveStatus {
  dynamics::DynamicsDesign design;
  dynamics::DynamicsParameters parameters;  // with the options' friction and zeroed masses
  dynamics::SinusoidalMotion motion;        // preload and stroke, m (omega = 0)
  mechanism::ForceOf force_of = mechanism::ForceOf::kWholeMechanism;
  int samples = 0;
  bool zero_slider_mass = false;
  bool zero_inertia = false;
  std::vector<double> omegas;                   // rad/s
  std::vector<dynamics::ForceStatistics> rows;  // per omega; forces of force_of, N
  std::vector<DynamicsForceHistory> histories;  // per history_omegas entry
  double static_nominal_force = 0.0;            // N, of force_of
  int static_force_points = 0;
  std::optional<double> paper_nominal_force;  // Table 6 F_Nom of force_of, N (built-ins)
  double natural_frequency = 0.0;             // unloaded, rad/s; 0 without inertia
  double seconds = 0.0;                       // wall time of the frequency sweep
};

// Checks the options and derives the parameters and the motion. Throws InvalidInput for bad
// options or a stroke that passes the toggle position. Cheap: call it before opening files.
DynamicsStudySetup dynamics_study_setup(const dynamics::DynamicsDesign& design,
                                        const DynamicsStudyOptions& options);

// The whole study. Throws InvalidInput as dynamics_study_setup; a mean or peak-to-peak force that
// is not finite stops the study with termination kNoConvergence and a message naming omega.
DynamicsStudy run_dynamics_study(const dynamics::DynamicsDesign& design,
                                 const DynamicsStudyOptions& options);

}  // namespace flexure
