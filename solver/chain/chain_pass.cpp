#include "flexure/solver/chain/chain_pass.h"

#include <algorithm>
#include <cmath>

#include "flexure/solver/chain/element_flexibility.h"

namespace flexure {

namespace {

// Chord of an arc of length L and curvature kappa0, accurate as kappa0 -> 0.
double arc_chord(double L, double kappa0) {
  const double half = 0.5 * kappa0 * L;
  if (std::abs(half) < 1e-4) return L * (1.0 - half * half / 6.0);
  return L * std::sin(half) / half;
}

}  // namespace

ChainGeometry unloaded_geometry(const ChainDiscretisation& d) {
  const int E = d.element_count();
  ChainGeometry g;
  g.x.assign(E + 1, 0.0);
  g.y.assign(E + 1, 0.0);
  g.theta.assign(E + 1, 0.0);
  for (int i = 1; i <= E; ++i) {
    const ChainElement& el = d.elements[i - 1];
    if (el.rigid) {
      const double psi = g.theta[i - 1] + el.angle_offset;
      g.x[i] = g.x[i - 1] + el.length * std::cos(psi);
      g.y[i] = g.y[i - 1] + el.length * std::sin(psi);
      g.theta[i] = psi;
    } else {
      const double chi = g.theta[i - 1] + 0.5 * el.kappa0 * el.length;
      const double c = arc_chord(el.length, el.kappa0);
      g.x[i] = g.x[i - 1] + c * std::cos(chi);
      g.y[i] = g.y[i - 1] + c * std::sin(chi);
      g.theta[i] = g.theta[i - 1] + el.kappa0 * el.length;
    }
  }
  return g;
}

ChainPassReport chain_pass(const ChainDiscretisation& d,
                           const ChainNodeLoads& loads,
                           const ChainGeometry& previous,
                           const ChainPassOptions& options,
                           ChainGeometry& next) {
  const int E = d.element_count();
  const std::vector<double>& xo = previous.x;
  const std::vector<double>& yo = previous.y;

  // Suffix sums over nodes j >= i of the dead loads: force, moment, and p_old x f, p_old . f.
  // Thread-local scratch keeps a pass allocation-free after the first call.
  thread_local std::vector<double> Fx, Fy, Ms, C, D;
  Fx.assign(E + 2, 0.0);
  Fy.assign(E + 2, 0.0);
  Ms.assign(E + 2, 0.0);
  C.assign(E + 2, 0.0);
  D.assign(E + 2, 0.0);
  for (int j = E; j >= 1; --j) {
    Fx[j] = Fx[j + 1] + loads.fx[j];
    Fy[j] = Fy[j + 1] + loads.fy[j];
    Ms[j] = Ms[j + 1] + loads.m[j];
    C[j] = C[j + 1] + xo[j] * loads.fy[j] - yo[j] * loads.fx[j];
    D[j] = D[j + 1] + xo[j] * loads.fx[j] + yo[j] * loads.fy[j];
  }
  // Follower force at the tip in the previous geometry; it turns with the downstream chain.
  const double qx_old = -loads.follower * std::sin(previous.theta[E]);
  const double qy_old = loads.follower * std::cos(previous.theta[E]);

  next.x.resize(E + 1);
  next.y.resize(E + 1);
  next.theta.resize(E + 1);
  next.x[0] = 0.0;
  next.y[0] = 0.0;
  next.theta[0] = 0.0;
  ChainPassReport report;
  for (int i = 1; i <= E; ++i) {
    const ChainElement& el = d.elements[i - 1];
    // Rigid rotation of the downstream chain relative to the previous geometry: the change of the
    // clamp angle of element i (Howell's Delta Theta_{i-1}, measured from the previous geometry).
    const double rho = next.theta[i - 1] - previous.theta[i - 1];
    const double cr = std::cos(rho);
    const double sr = std::sin(rho);
    if (el.rigid) {
      const double psi = next.theta[i - 1] + el.angle_offset;
      next.x[i] = next.x[i - 1] + el.length * std::cos(psi);
      next.y[i] = next.y[i - 1] + el.length * std::sin(psi);
      next.theta[i] = psi;
    } else {
      // Resultant force on element i's tip (eqs. 7.10-7.11 before resolving).
      const double qx = cr * qx_old - sr * qy_old;
      const double qy = sr * qx_old + cr * qy_old;
      const double Rx = Fx[i] + qx;
      const double Ry = Fy[i] + qy;
      // Eq. 7.12 with the rotated arms of eqs. 7.14-7.15: sum_j (R(rho) a_j) x f_j with
      // a_j = p_j - p_i (previous geometry) equals cos(rho) sum a_j x f_j - sin(rho) sum a_j . f_j.
      const double A = C[i + 1] - (xo[i] * Fy[i + 1] - yo[i] * Fx[i + 1]);
      const double B = D[i + 1] - (xo[i] * Fx[i + 1] + yo[i] * Fy[i + 1]);
      double M = Ms[i] + cr * A - sr * B;
      if (i < E) M += (xo[E] - xo[i]) * qy_old - (yo[E] - yo[i]) * qx_old;
      // Element frame: the chord of the stress-free arc (the clamp tangent psi_i when straight).
      const double chi = next.theta[i - 1] + 0.5 * el.kappa0 * el.length;
      const double tx = std::cos(chi);
      const double ty = std::sin(chi);
      const double P_ax = Rx * tx + Ry * ty;   // Howell eq. 7.10, tension positive
      const double P_tr = -Rx * ty + Ry * tx;  // Howell eq. 7.11
      const ElementFlexibility f = element_flexibility(el.length, el.EI, P_ax);
      if (!f.valid) {
        report.ok = false;
        report.failed_element = i - 1;
        return report;
      }
      if (options.implicit_rotation && i < E) {
        // The arms also turn with the element's own rotation t: M(t) = M + dM/dt (t - t_prev)
        // linearised about the previous geometry's rotation t_prev (where the arms above are
        // exact). Solving t = f23 P_tr + f33 M(t) for t is one Newton step of the implicit
        // element equation; at the fixed point t = t_prev, so the fixed point is unchanged.
        const double t_prev = previous.theta[i] - previous.theta[i - 1] - el.kappa0 * el.length;
        const double dM = -(sr * A + cr * B);
        const double denominator = 1.0 - f.f33 * dM;
        if (denominator > 0.0) {
          const double t = (f.f23 * P_tr + f.f33 * (M - dM * t_prev)) / denominator;
          M += dM * (t - t_prev);
        }
      }
      double delta_th = f.f23 * P_tr + f.f33 * M;  // Howell eq. 7.16
      double delta_tr = f.f22 * P_tr + f.f23 * M;
      double along = arc_chord(el.length, el.kappa0);
      if (options.curved_and_tapered_terms) {
        delta_th += el.d_f23 * P_tr + el.d_f33 * M;
        delta_tr += el.d_f22 * P_tr + el.d_f23 * M;
        if (el.kappa0 != 0.0) {
          // The stress-free arc lies h(s) = kappa0 s (L - s) / 2 off its chord (toward -n), so
          // the axial force adds the moment -P_ax h(s), and a rotation at s moves the tip by
          // -h(s) along the chord as well as (L - s) across it.
          const double L = el.length;
          const double k = el.kappa0 / el.EI;
          delta_th -= P_ax * k * L * L * L / 12.0;
          delta_tr -= P_ax * k * L * L * L * L / 24.0;
          along -= 0.5 * k * (M * L * L * L / 6.0 + P_tr * L * L * L * L / 12.0);
        }
      }
      if (options.foreshortening) {
        // 1/2 d^T G d with G = [36, -3L; -3L, 4L^2]/(30L), the geometric stiffness block of 7.29.
        const double L = el.length;
        along -= (36.0 * delta_tr * delta_tr - 6.0 * L * delta_tr * delta_th +
                  4.0 * L * L * delta_th * delta_th) /
                 (60.0 * L);
      }
      next.x[i] = next.x[i - 1] + along * tx - delta_tr * ty;  // eqs. 7.17, 7.19, 7.21
      next.y[i] = next.y[i - 1] + along * ty + delta_tr * tx;  // eqs. 7.18, 7.20, 7.22
      next.theta[i] = next.theta[i - 1] + el.kappa0 * el.length + delta_th;  // eq. 7.23
    }
    report.position_change = std::max({report.position_change,
                                       std::abs(next.x[i] - previous.x[i]),
                                       std::abs(next.y[i] - previous.y[i])});
    report.angle_change =
        std::max(report.angle_change, std::abs(next.theta[i] - previous.theta[i]));
  }
  return report;
}

}  // namespace flexure
