#include "flexure/solver/shooting/compressed_cantilever_stability.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <variant>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/shooting/tension_stability.h"

// The four-lane (AVX2) expansion, chosen at run time (TaylorStep).
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define FLEXURE_JACOBI_AVX2 1
#endif

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;
// The Taylor series of each step (below) has this order; a step is as long as the last two
// terms allow for kTruncation relative to each group of the state (Jorba & Zou, Experimental
// Mathematics 14 (2005) 99, sec. 3.2): 12 steps along the beam on the n = 2 sweep of
// docs/performance.md where GSL's Prince-Dormand 8(7) at rtol 1e-10 took 52, at a truncation
// error far below the margin's 1e-12.
constexpr int kOrder = 24;
constexpr double kTruncation = 1e-16;
constexpr int kMaxSteps = 100000;
// Sub-points of one step evaluated in one call of TaylorStep::at_angle.
constexpr int kChunk = 16;
// The re-integrated far end must meet the solution within this (rad; relative for the moment): the
// solve converges to about 1e-11; a larger gap means the result is not this chain's equilibrium.
constexpr double kTipAngleCheck = 1e-8;
// Newton in q = sqrt(sigma) stops when its step is below this times q: the error of the last
// iterate is then about the square of it (quadratic convergence), far below the 1e-9 of the
// general verdict's margin.
constexpr double kStepTolerance = 1e-7;
constexpr int kMaxIterations = 60;
// The search for sigma_1 stops here (margin above 1 - 1e-4) and leaves the equilibrium to the
// general verdict: a weakly compressed beam whose lowest mode lives in a short compressed stretch
// next to long tensioned ones makes the Jacobi solutions grow like exp(sqrt(sigma F . t)) and the
// integration stiff, and such margins are rare in practice (docs/stability.md).
constexpr double kMaxSigma = 1e4;

// The tangent (cos theta, sin theta) is integrated instead of theta: the right-hand side is then
// polynomial (t' = kappa R90 t, EI kappa = m): no sine and cosine per evaluation, and its Taylor
// coefficients follow from products alone (TaylorStep).
enum : int { kCos = 0, kSin, kM, kU, kV, kUs, kVs, kSize };

struct Jacobi {
  double fx = 0.0, fy = 0.0;  // F L^2 / EI
  double sigma = 1.0;
};

// The Taylor series at one point of the elastica and Jacobi system on the scaled beam:
//   c' = -s m, s' = c m, m' = f_x s - f_y c                      (t = (c, s), EI theta' = m),
//   u' = v, v' = sigma w u, u_s' = v_s, v_s' = w u + sigma w u_s  (w = F . t = f_x c + f_y s),
// polynomial, so its coefficients follow from the products' (Cauchy) recurrences (automatic
// differentiation; Jorba & Zou 2005): a_{k+1} = (the right-hand side)_k / (k + 1).
class TaylorStep {
 public:
  // Where the processor has AVX2 the expansion and the evaluations run on four lanes
  // (expand_avx2 and the others below): each lane does the operations of the two-lane code in
  // the same order (no fused multiply-add: AVX2 alone enables none), so the same values, with half
  // the instructions; the Cauchy products of the expansion bound the verdict's speed.
  void expand(const double y[kSize], double fx, double fy, double sigma) {
#ifdef FLEXURE_JACOBI_AVX2
    if (kAvx2) {
      expand_avx2(y, fx, fy, sigma);
      return;
    }
#endif
    expand_sse(y, fx, fy, sigma);
  }
  void at(double d, double out[kSize]) const {
#ifdef FLEXURE_JACOBI_AVX2
    if (kAvx2) {
      at_avx2(d, out);
      return;
    }
#endif
    at_sse(d, out);
  }
  void at_angle(const double* d, int count, double* c, double* s, double* u, double* v) const {
#ifdef FLEXURE_JACOBI_AVX2
    if (kAvx2) {
      at_angle_avx2(d, count, c, s, u, v);
      return;
    }
#endif
    at_angle_sse(d, count, c, s, u, v);
  }

  void expand_sse(const double y[kSize], double fx, double fy, double sigma) {
    for (int i = 0; i < kSize; ++i) a_[i][0] = y[i];
    double* c = a_[kCos];
    double* sn = a_[kSin];
    double* m = a_[kM];
    double* u = a_[kU];
    double* v = a_[kV];
    double* us = a_[kUs];
    double* vs = a_[kVs];
    // The factors of the Cauchy products in pairs that share the other factor: (sin, cos) times
    // m and (u, u_sigma) times w, each pair one two-lane multiply and add (SSE2; a lane does the
    // operations of the scalar sum, in the same order, so the same values).
    sc_[0] = V2{sn[0], c[0]};
    uu_[0] = V2{u[0], us[0]};
    by_order_[0][0] = V2{c[0], sn[0]};
    by_order_[0][1] = V2{m[0], u[0]};
    by_order_[0][2] = V2{v[0], us[0]};
    by_order_[0][3] = V2{vs[0], 0.0};
    for (int k = 0; k < kOrder; ++k) {
      w_[k] = fx * c[k] + fy * sn[k];
      // The four Cauchy products, each summed in two interleaved halves (even and odd j): eight
      // independent sums instead of four chains of dependent additions, which bounded the
      // expansion's speed (docs/performance.md); the order of the additions changes the sums by
      // rounding only.
      V2 scm = {0.0, 0.0}, wuu = {0.0, 0.0};
      V2 scm2 = {0.0, 0.0}, wuu2 = {0.0, 0.0};
      int j = 0;
      for (; j + 1 <= k; j += 2) {
        scm += sc_[j] * m[k - j];
        wuu += w_[j] * uu_[k - j];
        scm2 += sc_[j + 1] * m[k - j - 1];
        wuu2 += w_[j + 1] * uu_[k - j - 1];
      }
      if (j == k) {
        scm += sc_[j] * m[0];
        wuu += w_[j] * uu_[0];
      }
      scm += scm2;
      wuu += wuu2;
      const double sm = scm[0], cm = scm[1], wu = wuu[0], wus = wuu[1];
      const double inv = kInverse[k];
      // Built from the new values in registers (reading them back from the arrays just written
      // stalls the chain of orders on the store).
      const double c_next = -sm * inv, sn_next = cm * inv;
      const double u_next = v[k] * inv, us_next = vs[k] * inv;
      c[k + 1] = c_next;
      sn[k + 1] = sn_next;
      m[k + 1] = (fx * sn[k] - fy * c[k]) * inv;
      u[k + 1] = u_next;
      v[k + 1] = sigma * wu * inv;
      us[k + 1] = us_next;
      vs[k + 1] = (wu + sigma * wus) * inv;
      sc_[k + 1] = V2{sn_next, c_next};
      uu_[k + 1] = V2{u_next, us_next};
      // By order for the evaluation (at()): the components of one order side by side, stored
      // as they are made (a transposing pass afterwards reloaded every coefficient).
      by_order_[k + 1][0] = V2{c_next, sn_next};
      by_order_[k + 1][1] = V2{m[k + 1], u_next};
      by_order_[k + 1][2] = V2{v[k + 1], us_next};
      by_order_[k + 1][3] = V2{vs[k + 1], 0.0};
    }
  }
  // The step length: the last two terms of each group (elastica; u and EI u'; their sigma-
  // derivatives) at most kTruncation times the group's size.
  // The smallest of the groups' ratios is taken before the root (x^(1/k) increases with x): two
  // powers per step instead of six, the same step.
  double step() const {
    double ratio[2] = {HUGE_VAL, HUGE_VAL};  // for the terms of order kOrder - 1 and kOrder
    const auto group = [&](int first, int last, double size) {
      if (!(size > 0.0)) return;
      for (int t = 0; t < 2; ++t) {
        const int k = kOrder - 1 + t;
        double largest = 0.0;
        for (int i = first; i <= last; ++i) largest = std::max(largest, std::fabs(a_[i][k]));
        if (largest > 0.0) ratio[t] = std::min(ratio[t], kTruncation * size / largest);
      }
    };
    group(kCos, kM, std::max(1.0, std::fabs(a_[kM][0])));
    const double uv = std::hypot(a_[kU][0], a_[kV][0]);
    group(kU, kV, uv);
    group(kUs, kVs, std::hypot(a_[kUs][0], a_[kVs][0]) + uv);
    double h = HUGE_VAL;
    for (int t = 0; t < 2; ++t) {
      if (ratio[t] < HUGE_VAL) h = std::min(h, std::pow(ratio[t], 1.0 / (kOrder - 1 + t)));
    }
    return h;
  }
  // Every component of the series at distance d (Horner), the components' recurrences side by
  // side (vectorised): the same operations per component, so the same values.
  void at_sse(double d, double out[kSize]) const {
    V2 r[kPairs];
    for (int p = 0; p < kPairs; ++p) r[p] = by_order_[kOrder][p];
    for (int k = kOrder - 1; k >= 0; --k) {
      for (int p = 0; p < kPairs; ++p) r[p] = r[p] * d + by_order_[k][p];
    }
    for (int i = 0; i < kSize; ++i) out[i] = r[i / 2][i % 2];
  }
  // The tangent (cos, sin) and u, EI u' at `count` distances d[0..count) (the Pruefer angle's
  // sub-points): the pairs of at() that hold them, by the same Horner recurrences (so the same
  // values), the sub-points' recurrences interleaved in groups of up to kGroup so that they
  // overlap (one Horner recurrence is a chain of dependent multiplies and adds).
  void at_angle_sse(const double* d, int count, double* c, double* s, double* u, double* v) const {
    for (int first = 0; first < count; first += kGroup) {
      const int n = std::min(kGroup, count - first);
      if (n == kGroup) {
        at_angle_group<kGroup>(d + first, c + first, s + first, u + first, v + first);
      } else {
        for (int i = 0; i < n; ++i) {
          at_angle_group<1>(
              d + first + i, c + first + i, s + first + i, u + first + i, v + first + i);
        }
      }
    }
  }

#ifdef FLEXURE_JACOBI_AVX2
  // expand_sse on four lanes: (sin, cos, w, w) times (m, m, u, u_sigma) is both pairs of Cauchy
  // products at once; the even and odd halves and their order as there.
  __attribute__((target("avx2"))) void expand_avx2(const double y[kSize],
                                                   double fx,
                                                   double fy,
                                                   double sigma) {
    for (int i = 0; i < kSize; ++i) a_[i][0] = y[i];
    double* c = a_[kCos];
    double* sn = a_[kSin];
    double* m = a_[kM];
    double* u = a_[kU];
    double* v = a_[kV];
    double* us = a_[kUs];
    double* vs = a_[kVs];
    mu_[0] = V4{m[0], m[0], u[0], us[0]};
    by_order4_[0][0] = V4{c[0], sn[0], m[0], u[0]};
    by_order4_[0][1] = V4{v[0], us[0], vs[0], 0.0};
    for (int k = 0; k < kOrder; ++k) {
      const double w = fx * c[k] + fy * sn[k];
      scw_[k] = V4{sn[k], c[k], w, w};
      // The terms before the newest (j < k) on four lanes; the newest, j = k, last into its half
      // (even or odd j) as in expand_sse, on two lanes each: the newest coefficients go from the
      // registers into (sin, cos) times m without waiting for w or crossing lanes, which is the
      // chain from one order to the next (the older terms are ready early).
      V4 acc = {0.0, 0.0, 0.0, 0.0}, acc2 = {0.0, 0.0, 0.0, 0.0};
      int j = 0;
      for (; j + 2 <= k; j += 2) {
        acc += scw_[j] * mu_[k - j];
        acc2 += scw_[j + 1] * mu_[k - j - 1];
      }
      if (j + 1 == k) acc += scw_[j] * mu_[1];
      V2 sc_lo = {acc[0], acc[1]}, wu_hi = {acc[2], acc[3]};
      V2 sc_lo2 = {acc2[0], acc2[1]}, wu_hi2 = {acc2[2], acc2[3]};
      const V2 newest_sc = V2{sn[k], c[k]} * m[0];
      const V2 newest_wu = w * V2{u[0], us[0]};
      if (k % 2 == 0) {
        sc_lo += newest_sc;
        wu_hi += newest_wu;
      } else {
        sc_lo2 += newest_sc;
        wu_hi2 += newest_wu;
      }
      sc_lo += sc_lo2;
      wu_hi += wu_hi2;
      const double sm = sc_lo[0], cm = sc_lo[1], wu = wu_hi[0], wus = wu_hi[1];
      const double inv = kInverse[k];
      const double c_next = -sm * inv, sn_next = cm * inv;
      const double u_next = v[k] * inv, us_next = vs[k] * inv;
      const double m_next = (fx * sn[k] - fy * c[k]) * inv;
      const double v_next = sigma * wu * inv;
      const double vs_next = (wu + sigma * wus) * inv;
      c[k + 1] = c_next;
      sn[k + 1] = sn_next;
      m[k + 1] = m_next;
      u[k + 1] = u_next;
      v[k + 1] = v_next;
      us[k + 1] = us_next;
      vs[k + 1] = vs_next;
      mu_[k + 1] = V4{m_next, m_next, u_next, us_next};
      by_order4_[k + 1][0] = V4{c_next, sn_next, m_next, u_next};
      by_order4_[k + 1][1] = V4{v_next, us_next, vs_next, 0.0};
    }
  }
  __attribute__((target("avx2"))) void at_avx2(double d, double out[kSize]) const {
    V4 r0 = by_order4_[kOrder][0], r1 = by_order4_[kOrder][1];
    for (int k = kOrder - 1; k >= 0; --k) {
      r0 = r0 * d + by_order4_[k][0];
      r1 = r1 * d + by_order4_[k][1];
    }
    out[kCos] = r0[0];
    out[kSin] = r0[1];
    out[kM] = r0[2];
    out[kU] = r0[3];
    out[kV] = r1[0];
    out[kUs] = r1[1];
    out[kVs] = r1[2];
  }
  __attribute__((target("avx2"))) void at_angle_avx2(
      const double* d, int count, double* c, double* s, double* u, double* v) const {
    constexpr int kAvxGroup = 4;  // 4 sub-points x 2 accumulators
    int first = 0;
    for (; first + kAvxGroup <= count; first += kAvxGroup) {
      V4 r[kAvxGroup][2];
      for (int j = 0; j < kAvxGroup; ++j) {
        r[j][0] = by_order4_[kOrder][0];
        r[j][1] = by_order4_[kOrder][1];
      }
      for (int k = kOrder - 1; k >= 0; --k) {
        for (int j = 0; j < kAvxGroup; ++j) {
          r[j][0] = r[j][0] * d[first + j] + by_order4_[k][0];
          r[j][1] = r[j][1] * d[first + j] + by_order4_[k][1];
        }
      }
      for (int j = 0; j < kAvxGroup; ++j) {
        c[first + j] = r[j][0][0];
        s[first + j] = r[j][0][1];
        u[first + j] = r[j][0][3];
        v[first + j] = r[j][1][0];
      }
    }
    for (; first < count; ++first) {
      V4 r0 = by_order4_[kOrder][0], r1 = by_order4_[kOrder][1];
      for (int k = kOrder - 1; k >= 0; --k) {
        r0 = r0 * d[first] + by_order4_[k][0];
        r1 = r1 * d[first] + by_order4_[k][1];
      }
      c[first] = r0[0];
      s[first] = r0[1];
      u[first] = r0[3];
      v[first] = r1[0];
    }
  }
#endif

 private:
  using V2 = double __attribute__((vector_size(16)));
  // 1 / (k + 1), the factor of the recurrences (a table: no division in the loop).
  static constexpr auto kInverse = [] {
    std::array<double, kOrder> t{};
    for (int k = 0; k < kOrder; ++k) t[k] = 1.0 / (k + 1);
    return t;
  }();
  double a_[kSize][kOrder + 1] = {};
  double w_[kOrder + 1] = {};
  V2 sc_[kOrder + 1] = {};
  V2 uu_[kOrder + 1] = {};
  static constexpr int kPairs = (kSize + 1) / 2;
#ifdef FLEXURE_JACOBI_AVX2
  using V4 = double __attribute__((vector_size(32)));
  inline static const bool kAvx2 = __builtin_cpu_supports("avx2");
  V4 scw_[kOrder + 1] = {};
  V4 mu_[kOrder + 1] = {};
  // by order: (cos, sin, m, u) and (EI u', u_sigma, EI u_sigma', 0)
  V4 by_order4_[kOrder + 1][2] = {};
#endif
  // Sub-points evaluated together by at_angle: three pairs each, 3 x 4 = 12 accumulators.
  static constexpr int kGroup = 4;
  template <int N>
  void at_angle_group(const double* d, double* c, double* s, double* u, double* v) const {
    V2 r[N][3];
    for (int j = 0; j < N; ++j) {
      for (int p = 0; p < 3; ++p) r[j][p] = by_order_[kOrder][p];
    }
    for (int k = kOrder - 1; k >= 0; --k) {
      for (int j = 0; j < N; ++j) {
        for (int p = 0; p < 3; ++p) r[j][p] = r[j][p] * d[j] + by_order_[k][p];
      }
    }
    for (int j = 0; j < N; ++j) {
      c[j] = r[j][0][0];
      s[j] = r[j][0][1];
      u[j] = r[j][1][1];
      v[j] = r[j][2][0];
    }
  }
  V2 by_order_[kOrder + 1][kPairs] = {};
};

// One integration at sigma. `f` is the eigen-condition, decreasing through 0 at every eigenvalue:
// forward (from the clamp, u(0) = 0) pi/2 - phi(L), backward (from the tip, EI u'(L) = 0) the
// angle atan2(u, EI u') at the clamp; `count` the eigenvalues below 1 - 1/sigma.
struct Pass {
  double f = 0.0;
  double df = 0.0;  // d f / d sigma
  int count = 0;
  double end_cos = 1.0;  // the tangent where the integration ended (the tip, or the clamp)
  double end_sin = 0.0;
  double end_m = 0.0;  // m there
  double gamma = 0.0;  // int sqrt(max(0, -F . t)) ds (scaled), the straight column's guess
  bool ok = false;
};

class JacobiPasses {
 public:
  // From the clamp (theta 0, moment m0) or, `backward`, from the tip (theta_tip, m_tip).
  JacobiPasses(double fx, double fy, double m0, double theta_tip, double m_tip, bool backward)
      : m0_(m0), m_tip_(m_tip), backward_(backward) {
    params_.fx = fx;
    params_.fy = fy;
    force_ = std::hypot(fx, fy);
    cos_tip_ = std::cos(theta_tip);  // once, not in every pass
    sin_tip_ = std::sin(theta_tip);
  }

  Pass run(double sigma) {
    Pass out;
    params_.sigma = sigma;
    // Forward: u(0) = 0, EI u'(0) = 1. Backward: u(L) = 1, EI u'(L) = 0.
    double y[kSize] = {1.0, 0.0, m0_, 0.0, 1.0, 0.0, 0.0};
    if (backward_) {
      y[kCos] = cos_tip_;
      y[kSin] = sin_tip_;
      y[kM] = m_tip_;
      y[kU] = 1.0;
      y[kV] = 0.0;
    }
    const double t_end = backward_ ? 0.0 : 1.0;
    const double direction = backward_ ? -1.0 : 1.0;
    // The Pruefer angle turns by at most about one radian over this length (see the header): the
    // angle is unwrapped on sub-points this far apart, read off each step's Taylor polynomial.
    const double h_turn = 1.0 / std::max(1.0, std::sqrt(sigma * force_));
    double t = backward_ ? 1.0 : 0.0;
    double angle = std::atan2(y[kU], y[kV]);  // at the last sub-point
    double phi = angle;                       // unwrapped
    const auto compression = [&](double c, double sn) {
      return std::sqrt(std::max(0.0, -(params_.fx * c + params_.fy * sn)));
    };
    double g_before = compression(y[kCos], y[kSin]);
    for (int steps = 0; direction * (t_end - t) > 0.0; ++steps) {
      if (steps > kMaxSteps) return out;
      taylor_.expand(y, params_.fx, params_.fy, sigma);
      double h = direction * std::min(taylor_.step(), direction * (t_end - t));
      const bool last = std::fabs(h) >= direction * (t_end - t);
      if (last) h = t_end - t;
      // Sub-points for the angle (and the compression integral of the straight column's guess).
      const int sub = std::max(1, static_cast<int>(std::ceil(std::fabs(h) / h_turn)));
      const auto advance = [&](double c, double sn, double u, double v) {
        const double now = std::atan2(u, v);
        double turn = now - angle;
        if (turn > kPi) turn -= 2.0 * kPi;
        if (turn <= -kPi) turn += 2.0 * kPi;
        phi += turn;
        angle = now;
        const double g_after = compression(c, sn);
        out.gamma += 0.5 * std::fabs(h) / sub * (g_before + g_after);
        g_before = g_after;
      };
      // The sub-points before the step's end: only the tangent and u, EI u', several at a time
      // (TaylorStep::at_angle; the same values as at()).
      for (int k0 = 1; k0 < sub; k0 += kChunk) {
        const int n = std::min(kChunk, sub - k0);
        double d[kChunk], c[kChunk], sn[kChunk], u[kChunk], v[kChunk];
        for (int i = 0; i < n; ++i) d[i] = h * (k0 + i) / sub;
        taylor_.at_angle(d, n, c, sn, u, v);
        for (int i = 0; i < n; ++i) advance(c[i], sn[i], u[i], v[i]);
      }
      double point[kSize];
      taylor_.at(h * sub / sub, point);
      advance(point[kCos], point[kSin], point[kU], point[kV]);
      // The end of the step is the last sub-point when its distance is h to the bit (always for
      // one sub-point): the same evaluation, done once.
      if (h * sub / sub == h) {
        std::copy(point, point + kSize, y);
      } else {
        taylor_.at(h, y);
      }
      t = last ? t_end : t + h;
      if (!std::isfinite(y[kU]) || !std::isfinite(y[kV]) || !std::isfinite(y[kUs]) ||
          !std::isfinite(y[kVs]) || !std::isfinite(y[kM])) {
        return out;
      }
      // Keep the linear solution of order one (it grows exponentially in tension): the angle
      // and its derivative are invariant under scaling u, v, u_sigma, v_sigma together.
      // (hypot only near the limits: r lies between max(|u|, |v|) and sqrt(2) times it.)
      const double larger = std::max(std::fabs(y[kU]), std::fabs(y[kV]));
      if (larger > 7e99 || larger < 1e-100) {
        const double r = std::hypot(y[kU], y[kV]);
        if (r > 1e100 || r < 1e-100) {
          for (int k = kU; k < kSize; ++k) y[k] /= r;
          angle = std::atan2(y[kU], y[kV]);
        }
      }
    }
    // The count from the unwrapped angle; the eigen-condition from the modified angle
    // atan2(S u, v), S = (1 + (sigma w)^2)^(1/4) at the end (Pruefer's scaled angle; Pryce,
    // Numerical Solution of Sturm-Liouville Problems, 1993, sec. 5.2), which meets the multiples of
    // pi/2 where the plain one does (S > 0) and, as a function of sigma, is nearly linear in
    // sqrt(sigma) where the end is compressed (a straight column: S u / v = tan(sqrt(sigma P) L)),
    // so Newton's method converges from further away.
    const double w_end = params_.fx * y[kCos] + params_.fy * y[kSin];
    const double A = 1.0 + sigma * sigma * w_end * w_end;
    const double S = std::sqrt(std::sqrt(A));
    const double dS = sigma * w_end * w_end / (2.0 * S * S * S);
    const double modified = phi + (std::atan2(S * y[kU], y[kV]) - std::atan2(y[kU], y[kV]));
    const double d_modified = (y[kV] * (dS * y[kU] + S * y[kUs]) - S * y[kU] * y[kVs]) /
                              (y[kV] * y[kV] + S * S * y[kU] * y[kU]);
    if (backward_) {
      // Integrated from s = L down to 0, the angle decreases with sigma; u(0) = 0 at an
      // eigenvalue: phi(0) = 0 at the first, -pi at the second, ...
      out.f = modified;
      out.df = d_modified;
      out.count = phi <= 0.0 ? static_cast<int>(std::floor(-phi / kPi)) + 1 : 0;
    } else {
      out.f = 0.5 * kPi - modified;
      out.df = -d_modified;
      out.count = static_cast<int>(std::floor((phi + 0.5 * kPi) / kPi));
    }
    out.end_cos = y[kCos];
    out.end_sin = y[kSin];
    out.end_m = y[kM];
    out.ok = std::isfinite(out.f) && std::isfinite(out.df) && out.count >= 0;
    return out;
  }

 private:
  Jacobi params_;
  double m0_ = 0.0, m_tip_ = 0.0, force_ = 0.0;
  double cos_tip_ = 1.0, sin_tip_ = 0.0;
  bool backward_ = false;
  TaylorStep taylor_;
};

// compressed_cantilever_stability() with or without the guess (no fallback).
std::optional<Stability> jacobi_verdict(const SegmentChain& chain,
                                        const ShootingResult& result,
                                        const StabilityOptions& options,
                                        std::optional<double> margin_guess) {
  if (!tension_verdict_applies(chain) || !result.converged()) return std::nullopt;
  options.validate();
  const auto& segment = std::get<FlexibleSegment>(chain.segments.front());
  const double L = segment.length, EI = segment.EI;
  const double fx = chain.tip_load.Fx * L * L / EI, fy = chain.tip_load.Fy * L * L / EI;
  const double m0 = -result.reaction.M * L / EI;
  if (!std::isfinite(fx) || !std::isfinite(fy) || !std::isfinite(m0) ||
      !std::isfinite(result.tip.theta)) {
    return std::nullopt;
  }
  const double tolerance = options.critical_tolerance;
  const auto verdict = [&](int index, double margin) {
    return classify_stability(index, margin, tolerance, "the beam");
  };
  // No force: W = 0, every eigenvalue is 1 (the unloaded beam).
  if (fx == 0.0 && fy == 0.0) return verdict(0, 1.0);
  // The direction in which the eigen-condition is well conditioned: into the clamp when the beam
  // is compressed there (the Jacobi solutions oscillate there and grow, if at all, towards the
  // tip, where the backward integration starts on its natural condition), else from it.
  const bool backward = fx < 0.0;
  const double m_tip = chain.tip_load.M * L / EI;
  JacobiPasses passes(fx, fy, m0, result.tip.theta, m_tip, backward);

  // The re-integrated elastica must end where the solution does (the tip angle, or the clamp's
  // angle 0 and moment), compared on the tangent (the angle modulo 2 pi: the pass integrates
  // cos theta and sin theta).
  const auto meets = [&](const Pass& p) {
    if (backward) {
      return std::fabs(std::atan2(p.end_sin, p.end_cos)) <= kTipAngleCheck &&
             std::fabs(p.end_m - m0) <= kTipAngleCheck * std::max(1.0, std::fabs(m0));
    }
    const double c = std::cos(result.tip.theta), s = std::sin(result.tip.theta);
    // The angle from the solution's tangent to the pass's.
    return std::fabs(std::atan2(c * p.end_sin - s * p.end_cos, c * p.end_cos + s * p.end_sin)) <=
           kTipAngleCheck;
  };
  // The index: eigenvalues below -tolerance, i.e. the count at sigma_t = 1 / (1 + tolerance).
  const double sigma_t = 1.0 / (1.0 + tolerance);
  const double q_max = std::sqrt(kMaxSigma);
  // The lowest eigenvalue: f(sigma) = 0, sigma = q^2; f > 0 exactly below sigma_1 (the count is
  // nondecreasing in sigma), so its sign brackets q_1.
  double q_lo = 0.0, q_hi = HUGE_VAL;
  double q = 0.0;
  std::optional<int> index;
  const bool guessed = margin_guess && std::isfinite(*margin_guess) && *margin_guess < 1.0;
  if (guessed) {
    // A sweep's prediction from its neighbours' margins (beam_sweep_solver.h): Newton's method
    // starts there, the index pass is left out unless sigma_1 turns out below sigma_t (an index
    // of 0 follows from sigma_1 >= sigma_t alone: sigma_1 is the lowest eigenvalue's).
    q = std::sqrt(1.0 / (1.0 - *margin_guess));
    if (!(q < q_max)) q = 0.5 * q_max;
  } else {
    const Pass first = passes.run(sigma_t);
    if (!first.ok || !meets(first)) return std::nullopt;
    index = first.count;
    if (*index == 0) {
      q_lo = std::sqrt(sigma_t);
    } else {
      q_hi = std::sqrt(sigma_t);
    }
    // No compression at the first pass's steps: the shape is in tension nearly everywhere, its
    // margin close to 1, which the general verdict resolves.
    if (!(first.gamma > 0.0)) return std::nullopt;
    // The straight column's guess: q int sqrt(max(0, -F . t)) ds = pi/2.
    q = 0.5 * kPi / first.gamma;
    if (!(q > q_lo && q < q_hi)) {
      q = std::isfinite(q_hi) ? 0.5 * (q_lo + q_hi) : std::min(2.0 * q_lo, q_max);
    }
  }
  for (int iteration = 0;; ++iteration) {
    if (iteration >= kMaxIterations) return std::nullopt;
    if (q_lo >= q_max) return std::nullopt;
    const Pass p = passes.run(q * q);
    if (!p.ok) return std::nullopt;
    if (iteration == 0 && guessed && (!meets(p) || !(p.gamma > 0.0))) return std::nullopt;
    (p.f > 0.0 ? q_lo : q_hi) = q;
    const double slope = 2.0 * q * p.df;
    double next = slope < 0.0 ? q - p.f / slope : HUGE_VAL;
    if (std::fabs(next - q) <= kStepTolerance * q && next > 0.0) {
      q = next;
      break;
    }
    // From a guess the iterates may start far above sigma_1, where a step can overshoot past
    // q_max (passes there fail as the Jacobi solutions grow by e^300): kept below it.
    if (!(next > q_lo && next < q_hi) || (guessed && next >= q_max)) {
      next = std::isfinite(q_hi) ? 0.5 * (q_lo + q_hi) : std::min(2.0 * q, q_max);
    }
    if (std::isfinite(q_hi) && q_hi - q_lo <= 1e-15 * q_hi) {
      q = 0.5 * (q_lo + q_hi);
      break;
    }
    q = next;
  }
  // The bracket holds the answer exactly; the last Newton step may overshoot it by rounding.
  q = std::clamp(q, q_lo, q_hi);
  if (!index) {
    // sigma_1 clearly above sigma_t: no eigenvalue below -tolerance. Else (unstable or close to
    // critical) the count at sigma_t, as without a guess.
    if (q * q > sigma_t * (1.0 + 1e-8)) {
      index = 0;
    } else {
      const Pass at_t = passes.run(sigma_t);
      if (!at_t.ok) return std::nullopt;
      index = at_t.count;
    }
  }
  const double sigma_1 = q * q;
  const double margin = 1.0 - 1.0 / sigma_1;
  return verdict(*index, margin);
}

}  // namespace

std::optional<Stability> compressed_cantilever_stability(const SegmentChain& chain,
                                                         const ShootingResult& result,
                                                         const StabilityOptions& options,
                                                         std::optional<double> margin_guess) {
  if (margin_guess) {
    // Where the search from the guess does not settle (a pass fails far from sigma_1, or any
    // other reason to decline), the verdict is the one without it: a guess never changes it.
    if (std::optional<Stability> v = jacobi_verdict(chain, result, options, margin_guess)) return v;
  }
  return jacobi_verdict(chain, result, options, std::nullopt);
}

}  // namespace flexure
