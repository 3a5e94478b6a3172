#include "flexure/solver/shooting/prince_dormand87_piece.h"

#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <type_traits>
#include <utility>

namespace flexure {
namespace {

// RK8(7)13M (Prince & Dormand 1981, Table 2): the nodes c_i, the rows a_ij of the stages (zero
// entries left out), the eighth-order weights b_i (the step) and the seventh-order weights
// bhat_i (the error estimate), as the rationals of the paper. Stage i is written k_i, i = 1..13.
constexpr double c2 = 1.0 / 18.0, c3 = 1.0 / 12.0, c4 = 1.0 / 8.0, c5 = 5.0 / 16.0, c6 = 3.0 / 8.0,
                 c7 = 59.0 / 400.0, c8 = 93.0 / 200.0, c9 = 5490023248.0 / 9719169821.0,
                 c10 = 13.0 / 20.0, c11 = 1201146811.0 / 1299019798.0;
constexpr double a21 = 1.0 / 18.0;
constexpr double a31 = 1.0 / 48.0, a32 = 1.0 / 16.0;
constexpr double a41 = 1.0 / 32.0, a43 = 3.0 / 32.0;
constexpr double a51 = 5.0 / 16.0, a53 = -75.0 / 64.0, a54 = 75.0 / 64.0;
constexpr double a61 = 3.0 / 80.0, a64 = 3.0 / 16.0, a65 = 3.0 / 20.0;
constexpr double a71 = 29443841.0 / 614563906.0, a74 = 77736538.0 / 692538347.0,
                 a75 = -28693883.0 / 1125000000.0, a76 = 23124283.0 / 1800000000.0;
constexpr double a81 = 16016141.0 / 946692911.0, a84 = 61564180.0 / 158732637.0,
                 a85 = 22789713.0 / 633445777.0, a86 = 545815736.0 / 2771057229.0,
                 a87 = -180193667.0 / 1043307555.0;
constexpr double a91 = 39632708.0 / 573591083.0, a94 = -433636366.0 / 683701615.0,
                 a95 = -421739975.0 / 2616292301.0, a96 = 100302831.0 / 723423059.0,
                 a97 = 790204164.0 / 839813087.0, a98 = 800635310.0 / 3783071287.0;
constexpr double a101 = 246121993.0 / 1340847787.0, a104 = -37695042795.0 / 15268766246.0,
                 a105 = -309121744.0 / 1061227803.0, a106 = -12992083.0 / 490766935.0,
                 a107 = 6005943493.0 / 2108947869.0, a108 = 393006217.0 / 1396673457.0,
                 a109 = 123872331.0 / 1001029789.0;
constexpr double a111 = -1028468189.0 / 846180014.0, a114 = 8478235783.0 / 508512852.0,
                 a115 = 1311729495.0 / 1432422823.0, a116 = -10304129995.0 / 1701304382.0,
                 a117 = -48777925059.0 / 3047939560.0, a118 = 15336726248.0 / 1032824649.0,
                 a119 = -45442868181.0 / 3398467696.0, a1110 = 3065993473.0 / 597172653.0;
constexpr double a121 = 185892177.0 / 718116043.0, a124 = -3185094517.0 / 667107341.0,
                 a125 = -477755414.0 / 1098053517.0, a126 = -703635378.0 / 230739211.0,
                 a127 = 5731566787.0 / 1027545527.0, a128 = 5232866602.0 / 850066563.0,
                 a129 = -4093664535.0 / 808688257.0, a1210 = 3962137247.0 / 1805957418.0,
                 a1211 = 65686358.0 / 487910083.0;
constexpr double a131 = 403863854.0 / 491063109.0, a134 = -5068492393.0 / 434740067.0,
                 a135 = -411421997.0 / 543043805.0, a136 = 652783627.0 / 914296604.0,
                 a137 = 11173962825.0 / 925320556.0, a138 = -13158990841.0 / 6184727034.0,
                 a139 = 3936647629.0 / 1978049680.0, a1310 = -160528059.0 / 685178525.0,
                 a1311 = 248638103.0 / 1413531060.0;
constexpr double b1 = 14005451.0 / 335480064.0, b6 = -59238493.0 / 1068277825.0,
                 b7 = 181606767.0 / 758867731.0, b8 = 561292985.0 / 797845732.0,
                 b9 = -1041891430.0 / 1371343529.0, b10 = 760417239.0 / 1151165299.0,
                 b11 = 118820643.0 / 751138087.0, b12 = -528747749.0 / 2220607170.0,
                 b13 = 1.0 / 4.0;
constexpr double bh1 = 13451932.0 / 455176623.0, bh6 = -808719846.0 / 976000145.0,
                 bh7 = 1757004468.0 / 5645159321.0, bh8 = 656045339.0 / 265891186.0,
                 bh9 = -3867574721.0 / 1518517206.0, bh10 = 465885868.0 / 322736535.0,
                 bh11 = 53011238.0 / 667516719.0, bh12 = 2.0 / 45.0;
constexpr int kStages = 13;
constexpr int kArrays = kStages + 4;  // the stages, the trial state, y0, the error, f at the end

// The arrays of one step; `dim` the packed length (a compile-time constant in the instances for
// 0 to 4 sensitivity columns, so that the sums below are unrolled and vectorised).
struct Arrays {
  double* k[kStages];
  double* trial;
  double* y0;
  double* error;
  double* f_end;
};

// One step from (s, y) of length h, k[0] = f(s, y) given: y becomes the eighth-order solution,
// `error` the difference of the seventh- and eighth-order ones, f_end = f(s + h, y). The sums
// are GSL's rk8pd_apply's, term by term in the same order (see the header), and so is y0's role.
template <int kDim>
void step(const ElasticaPieceData& piece,
          int Ns,
          int dim_runtime,
          double s,
          double h,
          double* y,
          const Arrays& w) {
  const int dim = kDim > 0 ? kDim : dim_runtime;
  const int ns = kDim > 0 ? kDim / kElasticaStates - 1 : Ns;
  double* const* k = w.k;
  double* const t = w.trial;
  const double* const y0 = w.y0;
  std::copy(y, y + dim, w.y0);
  const auto f = [&](double at, const double* state, double* out) {
    if constexpr (kDim > 0) {
      if (!piece.extended) {
        plain_elastica_rhs(
            piece, at, state, out, std::integral_constant<int, kDim / kElasticaStates - 1>{});
        return;
      }
    }
    elastica_rhs(piece, at, state, out, ns);
  };
  const double h21 = a21 * h;
  for (int i = 0; i < dim; ++i) t[i] = y0[i] + h21 * k[0][i];
  f(s + c2 * h, t, k[1]);
  for (int i = 0; i < dim; ++i) t[i] = y0[i] + h * (a31 * k[0][i] + a32 * k[1][i]);
  f(s + c3 * h, t, k[2]);
  for (int i = 0; i < dim; ++i) t[i] = y0[i] + h * (a41 * k[0][i] + a43 * k[2][i]);
  f(s + c4 * h, t, k[3]);
  for (int i = 0; i < dim; ++i) {
    t[i] = y0[i] + h * (a51 * k[0][i] + a53 * k[2][i] + a54 * k[3][i]);
  }
  f(s + c5 * h, t, k[4]);
  for (int i = 0; i < dim; ++i) {
    t[i] = y0[i] + h * (a61 * k[0][i] + a64 * k[3][i] + a65 * k[4][i]);
  }
  f(s + c6 * h, t, k[5]);
  for (int i = 0; i < dim; ++i) {
    t[i] = y0[i] + h * (a71 * k[0][i] + a74 * k[3][i] + a75 * k[4][i] + a76 * k[5][i]);
  }
  f(s + c7 * h, t, k[6]);
  for (int i = 0; i < dim; ++i) {
    t[i] =
        y0[i] + h * (a81 * k[0][i] + a84 * k[3][i] + a85 * k[4][i] + a86 * k[5][i] + a87 * k[6][i]);
  }
  f(s + c8 * h, t, k[7]);
  for (int i = 0; i < dim; ++i) {
    t[i] = y0[i] + h * (a91 * k[0][i] + a94 * k[3][i] + a95 * k[4][i] + a96 * k[5][i] +
                        a97 * k[6][i] + a98 * k[7][i]);
  }
  f(s + c9 * h, t, k[8]);
  for (int i = 0; i < dim; ++i) {
    t[i] = y0[i] + h * (a101 * k[0][i] + a104 * k[3][i] + a105 * k[4][i] + a106 * k[5][i] +
                        a107 * k[6][i] + a108 * k[7][i] + a109 * k[8][i]);
  }
  f(s + c10 * h, t, k[9]);
  for (int i = 0; i < dim; ++i) {
    t[i] = y0[i] + h * (a111 * k[0][i] + a114 * k[3][i] + a115 * k[4][i] + a116 * k[5][i] +
                        a117 * k[6][i] + a118 * k[7][i] + a119 * k[8][i] + a1110 * k[9][i]);
  }
  f(s + c11 * h, t, k[10]);
  for (int i = 0; i < dim; ++i) {
    t[i] = y0[i] +
           h * (a121 * k[0][i] + a124 * k[3][i] + a125 * k[4][i] + a126 * k[5][i] + a127 * k[6][i] +
                a128 * k[7][i] + a129 * k[8][i] + a1210 * k[9][i] + a1211 * k[10][i]);
  }
  f(s + h, t, k[11]);
  for (int i = 0; i < dim; ++i) {
    t[i] = y0[i] +
           h * (a131 * k[0][i] + a134 * k[3][i] + a135 * k[4][i] + a136 * k[5][i] + a137 * k[6][i] +
                a138 * k[7][i] + a139 * k[8][i] + a1310 * k[9][i] + a1311 * k[10][i]);
  }
  f(s + h, t, k[12]);
  for (int i = 0; i < dim; ++i) {
    const double sum8 = b1 * k[0][i] + b6 * k[5][i] + b7 * k[6][i] + b8 * k[7][i] + b9 * k[8][i] +
                        b10 * k[9][i] + b11 * k[10][i] + b12 * k[11][i] + b13 * k[12][i];
    const double sum7 = bh1 * k[0][i] + bh6 * k[5][i] + bh7 * k[6][i] + bh8 * k[7][i] +
                        bh9 * k[8][i] + bh10 * k[9][i] + bh11 * k[10][i] + bh12 * k[11][i];
    y[i] = y0[i] + h * sum8;
    w.error[i] = h * (sum7 - sum8);
  }
  f(s + h, y, w.f_end);
}

enum class Adjust { kDecrease, kKeep, kIncrease };

// The standard step-size control of GSL (gsl_odeiv2_control_y_new; GSL manual, "Adaptive
// Step-size Control"): the largest ratio of the error to atol + rtol |y_i| above 1.1 shrinks the
// step by 0.9 r^(-1/8), at most 5x; below 0.5 it grows by 0.9 r^(-1/9), at least 1x and at most
// 5x (8 the order of the method).
template <int kDim>
Adjust control(
    double rtol, double atol, int dim_runtime, const double* y, const double* error, double& h) {
  const int dim = kDim > 0 ? kDim : dim_runtime;
  double largest = DBL_MIN;
  for (int i = 0; i < dim; ++i) {
    const double r = std::fabs(error[i]) / (rtol * std::fabs(y[i]) + atol);
    largest = r > largest ? r : largest;
  }
  // Where a factor is clamped its power is not needed: 0.9 r^(-1/8) < 0.2 for r > 4.5^8 =
  // 1.68e5, 0.9 r^(-1/9) > 5 for r < 0.18^9 = 1.98e-7 and < 1 for r > 0.9^9 = 0.387; the
  // thresholds below keep clear of those bounds by far more than pow's rounding, so h is the
  // same to the bit (the power was 5 % of a sweep's time).
  if (largest > 1.1) {
    h *= largest > 2e5 ? 0.2 : std::max(0.9 / std::pow(largest, 1.0 / 8.0), 0.2);
    return Adjust::kDecrease;
  }
  if (largest < 0.5) {
    if (largest < 1e-7) {
      h *= 5.0;
    } else if (largest <= 0.3875) {
      h *= std::max(std::min(0.9 / std::pow(largest, 1.0 / 9.0), 5.0), 1.0);
    }  // else the factor is 1
    return Adjust::kIncrease;
  }
  return Adjust::kKeep;
}

template <int kDim>
bool integrate_fixed(const PieceRun& run,
                     const ExplicitRkSettings& settings,
                     Arrays w,
                     double*& first_step_slot,
                     double& first_h,
                     bool& first_found) {
  const int dim = kDim > 0 ? kDim : kElasticaStates * (run.Ns + 1);
  double* y = run.y.data();
  double* f_start = w.k[0];
  double s = run.s_a;
  elastica_rhs(run.piece, s, y, f_start, run.Ns);
  // First step: the controller's proposal after the first step of the previous integration of
  // this piece; else from the tolerance (GslRk8pdPiece's rule).
  double h = std::min(
      run.s_b - run.s_a,
      first_step_slot != nullptr ? *first_step_slot : 0.5 * std::pow(settings.rtol, 1.0 / 8.0));
  bool first_accepted = false;
  long taken = 0;
  for (;;) {
    const bool to_shape_point = run.shape.pending_before(run.s_b);
    const double target =
        to_shape_point ? std::max((*run.shape.shape_s)[run.shape.next], s) : run.s_b;
    while (s < target) {
      if (++taken > run.max_steps) {
        run.error = fmt::format("rk8pd: more than {} steps at s = {}", run.max_steps, s);
        return false;
      }
      const bool final_step = h >= target - s;
      const double h_try = final_step ? target - s : h;
      step<kDim>(run.piece, run.Ns, dim, s, h_try, y, w);
      double h_next = h_try;
      const Adjust adjust = control<kDim>(settings.rtol, settings.atol, dim, y, w.error, h_next);
      if (!std::all_of(y, y + dim, [](double v) { return std::isfinite(v); })) {
        run.error = fmt::format("rk8pd: non-finite state at s = {}", s);
        return false;
      }
      if (adjust == Adjust::kDecrease) {
        // Rejected (the error above 1.1 times the tolerance): undo.
        std::copy(w.y0, w.y0 + dim, y);
        h = h_next;
        --taken;
        continue;
      }
      const double s_end = final_step ? target : s + h_try;
      if (run.observer != nullptr) {
        run.observer->accepted_step(run.piece, s, w.y0, w.k[0], s_end, y, w.f_end);
      }
      s = s_end;
      // The derivative at the end is the first stage of the next step.
      std::swap(w.k[0], w.f_end);
      // A step shortened to land on the target says nothing against the step before it.
      h = final_step && adjust != Adjust::kIncrease ? std::max(h, h_next) : h_next;
      if (!first_accepted) {
        first_accepted = true;
        first_found = true;
        first_h = h;
      }
    }
    if (!to_shape_point) break;
    run.shape.emit(y);
  }
  run.steps += taken;
  return true;
}

}  // namespace

bool PrinceDormand87Piece::integrate(const PieceRun& run) {
  const int dim = kElasticaStates * (run.Ns + 1);
  if (work_.size() < static_cast<std::size_t>(kArrays * dim)) work_.resize(kArrays * dim);
  Arrays w;
  for (int i = 0; i < kStages; ++i) w.k[i] = work_.data() + i * dim;
  w.trial = work_.data() + kStages * dim;
  w.y0 = w.trial + dim;
  w.error = w.y0 + dim;
  w.f_end = w.error + dim;
  double* slot = nullptr;
  for (FirstStep& f : first_step_) {
    if (f.segment == run.piece.segment && f.s_a == run.s_a) slot = &f.h;
  }
  double first_h = 0.0;
  bool first_found = false;
  bool ok = false;
  switch (run.Ns) {
    case 0:
      ok = integrate_fixed<4>(run, settings_, w, slot, first_h, first_found);
      break;
    case 1:
      ok = integrate_fixed<8>(run, settings_, w, slot, first_h, first_found);
      break;
    case 2:
      ok = integrate_fixed<12>(run, settings_, w, slot, first_h, first_found);
      break;
    case 3:
      ok = integrate_fixed<16>(run, settings_, w, slot, first_h, first_found);
      break;
    case 4:
      ok = integrate_fixed<20>(run, settings_, w, slot, first_h, first_found);
      break;
    default:
      ok = integrate_fixed<0>(run, settings_, w, slot, first_h, first_found);
      break;
  }
  if (first_found) {
    if (slot != nullptr) {
      *slot = first_h;
    } else {
      first_step_.push_back({run.piece.segment, run.s_a, first_h});
    }
  }
  return ok;
}

}  // namespace flexure
