#include "flexure/elements/cbcm_march.h"

#include <cmath>

#include "flexure/elements/ladder_models.h"

namespace flexure {

bool cbcm_march(int elements,
                double inverse_d,
                double m0,
                double Fx,
                double Fy,
                CbcmMarchResult& out,
                bool keep_nodes) {
  if (elements < 1 || !std::isfinite(m0) || !std::isfinite(Fx) || !std::isfinite(Fy) ||
      !(inverse_d >= 0.0) || !std::isfinite(inverse_d)) {
    return false;
  }
  const double h = 1.0 / elements;
  const double inverse_de = inverse_d * elements * elements;  // one element's 1/d: N^2/d
  ChainPose at;
  double M = m0;  // the distal loads' moment about the current node
  out.max_element_deflection = 0.0;
  out.nodes.clear();
  out.node_moments.clear();
  if (keep_nodes) {
    out.nodes.push_back(at);
    out.node_moments.push_back(M);
  }
  for (int j = 0; j < elements; ++j) {
    const double c = std::cos(at.theta), s = std::sin(at.theta);
    const double p = (Fx * c + Fy * s) * h * h;
    const double f = (-Fx * s + Fy * c) * h * h;
    const double hM = h * M;
    const bcm::Symmetric2 K = bcm::stiffness(p);
    // Newton on R1 = K11 y + K12 th - f, R2 = K12 y + K22 th - (hM - (1 + x) f + y p), from the
    // linear solution (x = p/d_e); converged to round-off of the element's loads.
    double y = 0.0, th = 0.0;
    bool done = false;
    const double scale = 1.0 + std::fabs(f) + std::fabs(hM) + std::fabs(p);
    for (int it = 0; it < 30; ++it) {
      const double x = bcm::axial_displacement(y, th, p, inverse_de);
      const double r1 = K.a11 * y + K.a12 * th - f;
      const double r2 = K.a12 * y + K.a22 * th - (hM - (1.0 + x) * f + y * p);
      if (it > 0 && std::fabs(r1) + std::fabs(r2) <= 1e-15 * scale) {
        done = true;
        break;
      }
      // dx/du = -P u - 2 p Q u.
      const double dxdy =
          -(bcm::kP.a11 * y + bcm::kP.a12 * th) - 2.0 * p * (bcm::kQ.a11 * y + bcm::kQ.a12 * th);
      const double dxdt =
          -(bcm::kP.a12 * y + bcm::kP.a22 * th) - 2.0 * p * (bcm::kQ.a12 * y + bcm::kQ.a22 * th);
      const double j11 = K.a11, j12 = K.a12;
      const double j21 = K.a12 + f * dxdy - p, j22 = K.a22 + f * dxdt;
      const double det = j11 * j22 - j12 * j21;
      if (!(std::fabs(det) > 1e-14 * (std::fabs(j11 * j22) + std::fabs(j12 * j21)))) {
        return false;  // the element at its own buckling load
      }
      const double dy = (-r1 * j22 + r2 * j12) / det;
      const double dt = (-r2 * j11 + r1 * j21) / det;
      y += dy;
      th += dt;
      if (!std::isfinite(y) || !std::isfinite(th)) return false;
      if (std::fabs(dy) + std::fabs(dt) <= 1e-15 * (1.0 + std::fabs(y) + std::fabs(th))) {
        done = true;
        break;
      }
    }
    if (!done) return false;
    const double x = bcm::axial_displacement(y, th, p, inverse_de);
    // The moment about the tip node: m_j h = hM - (1 + x) f + y p (per EI/L: divide by h).
    M = (hM - (1.0 + x) * f + y * p) / h;
    at.x += h * ((1.0 + x) * c - y * s);
    at.y += h * ((1.0 + x) * s + y * c);
    at.theta += th;
    out.max_element_deflection = std::max(out.max_element_deflection, std::fabs(y));
    if (keep_nodes) {
      out.nodes.push_back(at);
      out.node_moments.push_back(M);
    }
  }
  out.x = at.x;
  out.y = at.y;
  out.theta = at.theta;
  out.m = M;
  return std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.theta) &&
         std::isfinite(out.m);
}

}  // namespace flexure
