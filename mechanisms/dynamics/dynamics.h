#pragma once
// The dynamics of the constant-force slider mechanism's PRBM slider-crank (docs/dynamics.md), one
// section each: the model (masses, inertias and the mechanism's kinematics), its inverse dynamics
// (the force a prescribed motion needs) and its forward dynamics (the motion a force history
// gives). Each is implemented in its own .cpp file.
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/common/status.h"

namespace flexure::dynamics {

// Lagrangian model of the PRBM slider-crank of a constant-force slider mechanism with one degree
// of freedom, the crank angle theta2 (docs/dynamics.md, derivation section). Unlike the
// nondimensional static model of mechanisms/cfm this is dimensional (SI units) because masses and
// frequencies enter.
//
// Geometry (the slider_crank.h convention): ground pivot at the origin, crank r2 at theta2,
// coupler r3 at the principal angle theta3 = asin(-(r2/r3) sin theta2) <= 0, slider on the x axis
// at r1 = r2 cos theta2 + r3 cos theta3; slider displacement Delta x = r2 + r3 - r1 (compression
// positive). Spring rotations psi1 = theta2, psi2 = theta2 - theta3, psi3 = -theta3 (zero when the
// mechanism is straight), V = 1/2 sum k_i psi_i^2 (paper eqs. 8-12).
//
// The whole symmetric mechanism is modelled: `halves` identical half-mechanisms (links 2 and 3
// with their springs) move with one slider of mass m_slider. The generalized force of the slider
// force F (pushing the slider towards the ground, F > 0 compresses) is Q_F = -F dr1/dtheta2.
struct DynamicsParameters {
  double r2 = 0.0;                  // crank length, m (> 0)
  double r3 = 0.0;                  // coupler length, m (> 0)
  double m2 = 0.0;                  // link 2 mass per half, kg (>= 0)
  double m3 = 0.0;                  // link 3 mass per half, kg (>= 0)
  double m_slider = 0.0;            // slider mass (one slider), kg (>= 0)
  double J_C2 = 0.0;                // link 2 inertia about its centre, kg m^2 (uniform bar:
                                    // m2 r2^2/12, see from_bar_links)
  double J_C3 = 0.0;                // link 3 inertia about its centre, kg m^2
  std::array<double, 3> k{};        // torsional springs at pivots 1, 2, 3 per half, N m
  double halves = 2.0;              // number of half-mechanisms sharing the slider (2: symmetric)
  std::array<double, 3> coulomb{};  // Coulomb friction moment at pivots 1..3 per half, N m (eq. 27)
  double axial_alpha = 0.0;         // angle of axial-force effect alpha of eq. 28, rad (0: off)
};

// Links modelled as uniform slender bars of the PRBM lengths (J_C = m r^2/12); throws
// InvalidInput for non-positive lengths, negative masses or springs.
DynamicsParameters from_bar_links(double r2,
                                  double r3,
                                  double m2,
                                  double m3,
                                  double m_slider,
                                  std::array<double, 3> k,
                                  double halves = 2.0);

// Everything the equation of motion needs at one crank angle.
struct ConfigurationTerms {
  double theta2 = 0.0;
  double theta3 = 0.0;           // principal coupler angle
  double g = 0.0;                // dtheta3/dtheta2
  double dg = 0.0;               // d2theta3/dtheta2^2
  double r1 = 0.0;               // ground-to-slider distance, m
  double dr1 = 0.0;              // dr1/dtheta2, m (< 0 on the compression branch theta2 > 0)
  double d2r1 = 0.0;             // d2r1/dtheta2^2, m
  double M = 0.0;                // generalized inertia, kg m^2
  double dM = 0.0;               // dM/dtheta2
  double V = 0.0;                // spring energy of the whole mechanism, J
  double dV = 0.0;               // dV/dtheta2, N m
  double d2V = 0.0;              // d2V/dtheta2^2, N m
  std::array<double, 3> dpsi{};  // dpsi_i/dtheta2 (all >= 0 on the valid branch)
};

class SliderCrankDynamics {
 public:
  // Throws InvalidInput for non-positive lengths, negative masses, inertias, springs, friction,
  // halves <= 0 or non-finite values.
  explicit SliderCrankDynamics(DynamicsParameters parameters);

  const DynamicsParameters& parameters() const { return p_; }
  double r_tot() const { return p_.r2 + p_.r3; }

  // Terms at theta2. Throws InvalidInput if (r2/r3) |sin theta2| >= 1 (the coupler cannot reach
  // the slider axis: past the toggle position).
  ConfigurationTerms terms(double theta2) const;
  // Same, returning false instead of throwing (for integrator right-hand sides).
  bool try_terms(double theta2, ConfigurationTerms& out) const;

  // Crank angle theta2 >= 0 at slider displacement Delta x (0 <= Delta x, before toggle); uses the
  // cancellation-free closed form of slider_crank.h (Weight eq. 2.1).
  double theta2_at(double delta_x) const;
  double delta_x_at(double theta2) const;

  // Quasi-static slider force of the whole mechanism at theta2 > 0: F = dV/dtheta2 / (-dr1/dtheta2)
  // (virtual work; equals halves * (k_ref/r2) * Phi of the static PRBM, Weight eq. 2.14).
  double static_force(double theta2) const;

  // Generalized friction force (eq. 27, derived): -sign_value * sum_i halves C_i dpsi_i/dtheta2,
  // where sign_value stands for sign(dtheta2/dt) (the caller may pass a smoothed sign).
  double friction_moment(const ConfigurationTerms& t, double sign_value) const;
  // Axial-force moment of eq. 28, tau_AF = F_static r2 alpha (1 + r2/sqrt(r3^2 - r2^2 alpha^2)).
  double axial_moment(const ConfigurationTerms& t) const;

  // Kinetic + spring energy at (theta2, dtheta2/dt).
  double energy(double theta2, double theta2_dot) const;

 private:
  DynamicsParameters p_;
};

// Inverse dynamics of the slider mechanism under a prescribed sinusoidal slider motion (the
// paper's test: "sinusoidal position input with amplitude equal to the full 40 % designed
// deflection with a slight pre-displacement to give a preload at full expansion"):
//   Delta x(t) = preload + stroke (1 - cos omega t)/2,
// and the input force F(t) of the whole mechanism from the equation of motion
//   M theta2'' + 1/2 M' theta2'^2 + V' = -F r1' + Q_CF + Q_AF          (docs/dynamics.md eq. D7)
// Frequency sweeps give per omega the mean, median, peak-to-peak force and the percent constant
// force 100 min F/max F (paper, PCF expression after Table 10) over one period.
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

// Forward dynamics of the slider mechanism with the beam layer's ODE integrator
// (solver/ode/ode_integrator.h, SUNDIALS CVODES): the equation of motion
//   M(theta2) theta2'' = -1/2 M'(theta2) theta2'^2 - V'(theta2) - F r1'(theta2) + Q_CF
// (docs/dynamics.md eq. D7) as a first-order system in (theta2, theta2'), driven by an input force
// F(t, theta2, theta2') of the whole mechanism (a prescribed force, a driving spring, or zero for a
// release). Coulomb friction is smoothed as tanh(theta2'/v) so that the right-hand side stays
// continuous; the axial-force term of eq. 28 is not used here (it is a force-measurement
// correction, not a physical moment).
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

// What `flexure dynamics` runs: the slider-crank parameters of one design (PRBM links r2, r3, the
// torsion springs of one half, the masses), from a built-in design of the paper's Table 5
// (builtin_designs.h) or from any dimensional MechanismDesign, e.g. a TOML file (docs/dynamics.md
// "Designs from TOML", docs/mechanisms.md "TOML").
//
// The springs follow a rule (DynamicsSpringRule), reported as `spring_rule`:
//   "table5-printed"   the constants printed in the paper's Table 5 (the built-in default: it
//                      reproduces the paper's Table 6 F_Nom, docs/dynamics.md §2);
//   "pure-bending", "table2", "table5"
//                      computed from each strip's b, h, L and E as `flexure mechanism analyze`
//                      does (builtin_designs.h spring_rule_factor; k = EI/L for pure bending,
//                      Howell eq. 5.14);
//   "given"            the TOML file's [dynamics] spring_constants;
//   none               a thesis design without fixed-fixed segments: its springs have one rule
//                      (s: EI/l, Howell eq. 5.14; l: gamma K_theta EI/l, eq. 5.72), as in analyze.

// The rule the springs of a DynamicsDesign follow (above).
enum class DynamicsSpringRule { kTable5Printed, kPureBending, kTable2, kTable5, kGiven };
// "table5-printed", "pure-bending", "table2", "table5", "given" (the JSON key and HDF5 attribute
// `spring_rule`; the middle three are mechanism::spring_rule_name's).
const char* to_string(DynamicsSpringRule rule);
// The rule of that name; throws InvalidInput listing the five.
DynamicsSpringRule dynamics_spring_rule_from_string(std::string_view name);
// A mechanism's spring rule (pure-bending, table2, table5) as the dynamics reports it.
DynamicsSpringRule dynamics_spring_rule(mechanism::SpringRule rule);

struct DynamicsDesign {
  std::string name;
  double r2 = 0.0;                                // PRBM crank, m
  double r3 = 0.0;                                // PRBM coupler, m
  double m2 = 0.0;                                // link 2 of one half, kg
  double m3 = 0.0;                                // link 3 of one half, kg
  double m_slider = 0.0;                          // the one slider, kg
  std::array<double, 3> k{};                      // torsion springs of one half at pivots 1-3, N m
  std::optional<DynamicsSpringRule> spring_rule;  // none: a thesis design's one rule (above)
  double F_nom_paper = 0.0;      // Table 6 F_Nom of the whole mechanism, N (0: none)
  std::optional<double> stroke;  // the design's own stroke, m (a TOML file's)
  // The material whose E set the springs (--material: a row of data/materials.csv) as the
  // library's one Material (solver/common/section.h), and its id; empty: none was given.
  std::optional<Material> material;
  std::string material_id;
};

// The optional [dynamics] table of a mechanism TOML file (io/toml_files.h): what a dimensional
// design lacks for dynamics. `source` and `line` place it for messages.
struct DynamicsData {
  std::optional<double> m2;        // kg, link 2 of one half (a uniform bar, J = m r^2/12)
  std::optional<double> m3;        // kg, link 3 of one half
  std::optional<double> m_slider;  // kg, the slider shared by both halves
  std::optional<std::array<double, 3>> spring_constants;  // N m per half, 0 at a pin
  std::string source;                                     // the file
  int line = 0;                                           // line of [dynamics]; 0: no table
};

// The masses a run needs: the --zero-slider-mass and --zero-inertia options set some to zero.
enum class MassesNeeded { kAll, kLinksOnly, kNone };

// Built-in design `name` of the paper's Table 5 (case-insensitive) with the printed springs, or
// with those of `rule` computed from the printed strip dimensions (builtin_designs.h). Throws
// InvalidInput for an unknown name, listing the nine. `material` (a row of data/materials.csv)
// replaces the strips' E for the springs of `rule`; with the printed springs (no rule), which are
// constants, it is refused (InvalidInput).
DynamicsDesign builtin_dynamics_design(const std::string& name,
                                       std::optional<mechanism::SpringRule> rule,
                                       const MaterialGrade* material = nullptr);

// A dimensional design with the masses and optional springs of `data`. Springs: data's
// spring_constants if given ("given"), else the design's spring rule (`rule` replaces it, as
// `mechanism analyze --spring-rule` does). Throws InvalidInput "SOURCE[:LINE]: ..." naming the
// field: a mass `needed` but missing, spring_constants with a spring at a pin or none at a flexure,
// or `rule` together with spring_constants. `material` replaces the design's E for the springs
// computed from its strips; refused together with spring_constants (which do not depend on E).
DynamicsDesign dynamics_design(mechanism::MechanismDesign design,
                               const DynamicsData& data,
                               MassesNeeded needed,
                               std::optional<mechanism::SpringRule> rule,
                               const MaterialGrade* material = nullptr);

}  // namespace flexure::dynamics
