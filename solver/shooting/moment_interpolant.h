#pragma once
// The bending moment inside one accepted step of an explicit integrator, as the quintic Hermite
// polynomial through m, m' and m'' at both ends of the step (m' = N_x sin theta - N_y cos theta and
// m'' = (N_x cos theta + N_y sin theta) theta' follow from the state; Howell eqs. 2.67-2.69). Its
// error is O(h^6) (Burden & Faires, Numerical Analysis, §3.4, Hermite interpolation), as accurate
// as the integrated state. Used by segment_moments.h (max |m|, strain energy) and
// inflection_count.h (sign changes of the curvature). Internal to solver/shooting.
#include <array>
#include <cmath>
#include <vector>

#include "flexure/solver/shooting/elastica_piece.h"

namespace flexure {

class MomentQuintic {
 public:
  // The step [s0, s1] of `piece` with the packed states y and their derivatives f at both ends.
  MomentQuintic(const ElasticaPieceData& piece,
                double s0,
                const double* y0,
                const double* f0,
                double s1,
                const double* y1,
                const double* f1) {
    const double h = s1 - s0;
    // m'' = (N_x cos theta + N_y sin theta) theta' (differentiating m' = N_x sin - N_y cos).
    auto second = [&](const double* y, const double* f) {
      return moment_second_derivative(piece, y == y0 ? s0 : s1, y, f);
    };
    // p(t), t = (s - s0)/h: p, p', p'' match m, h m', h^2 m'' at t = 0 and t = 1.
    c_[0] = y0[kElasticaM];
    c_[1] = h * f0[kElasticaM];
    c_[2] = 0.5 * h * h * second(y0, f0);
    const double r0 = y1[kElasticaM] - (c_[0] + c_[1] + c_[2]);
    const double r1 = h * f1[kElasticaM] - (c_[1] + 2.0 * c_[2]);
    const double r2 = h * h * second(y1, f1) - 2.0 * c_[2];
    c_[3] = 10.0 * r0 - 4.0 * r1 + 0.5 * r2;
    c_[4] = -15.0 * r0 + 7.0 * r1 - r2;
    c_[5] = 6.0 * r0 - 3.0 * r1 + 0.5 * r2;
  }

  // m at t = (s - s0)/h in [0, 1], and dm/dt.
  double operator()(double t) const {
    return c_[0] + t * (c_[1] + t * (c_[2] + t * (c_[3] + t * (c_[4] + t * c_[5]))));
  }
  double derivative(double t) const {
    return c_[1] + t * (2.0 * c_[2] + t * (3.0 * c_[3] + t * (4.0 * c_[4] + t * 5.0 * c_[5])));
  }

  // The interior extrema of p on (0, 1) (the zeros of the quartic p', bracketed on eight
  // sub-intervals and bisected to rounding), in increasing t.
  std::vector<double> interior_extrema() const {
    std::vector<double> out;
    // Most steps are short against the moment's wavelength: when |p'(0)| exceeds the sum of the
    // other terms' largest magnitudes on [0, 1] (by 1 %, far more than rounding), p' keeps its
    // sign there and the scan below would find nothing.
    const double others = 2.0 * std::fabs(c_[2]) + 3.0 * std::fabs(c_[3]) + 4.0 * std::fabs(c_[4]) +
                          5.0 * std::fabs(c_[5]);
    if (std::fabs(c_[1]) > 1.01 * others) return out;
    constexpr int kBrackets = 8;
    double a = 0.0, da = derivative(0.0);
    for (int i = 1; i <= kBrackets; ++i) {
      const double b = static_cast<double>(i) / kBrackets;
      const double db = derivative(b);
      if ((da < 0.0) != (db < 0.0)) {
        double lo = a, hi = b, dlo = da;
        for (int k = 0; k < 60 && hi - lo > 1e-15; ++k) {
          const double mid = 0.5 * (lo + hi);
          const double dm = derivative(mid);
          if ((dm < 0.0) == (dlo < 0.0)) {
            lo = mid;
            dlo = dm;
          } else {
            hi = mid;
          }
        }
        out.push_back(0.5 * (lo + hi));
      }
      a = b;
      da = db;
    }
    return out;
  }

 private:
  std::array<double, 6> c_{};
};

}  // namespace flexure
