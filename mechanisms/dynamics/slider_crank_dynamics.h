#pragma once
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
#include <array>

namespace flexure::dynamics {

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

}  // namespace flexure::dynamics
