#include "flexure/solver/shooting/dormand_prince_piece.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

namespace flexure {

bool DormandPrincePiece::integrate(const PieceRun& run) {
  // Dormand-Prince 5(4) (Hairer, Norsett & Wanner, Solving ODEs I, Table II.5.2), FSAL, error test
  // on state and sensitivities (the same reason as CVodeSetSensErrCon, docs/theory-shooting.md §4).
  constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  constexpr double a21 = 1.0 / 5;
  constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                   a54 = -212.0 / 729;
  constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                   a65 = -5103.0 / 18656;
  constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                   b6 = 11.0 / 84;
  // Error coefficients: b - b_hat (fourth-order weights 5179/57600, 0, 7571/16695, 393/640,
  // -92097/339200, 187/2100, 1/40).
  constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                   e6 = 22.0 / 525, e7 = -1.0 / 40;
  const int dim = kElasticaStates * (run.Ns + 1);
  std::vector<double> y_new(dim), tmp(dim), k1(dim), k2(dim), k3(dim), k4(dim), k5(dim), k6(dim),
      k7(dim);
  const double rtol = settings_.rtol, atol = settings_.atol;
  const double length = run.s_b - run.s_a;
  double s = run.s_a;
  // First step from the tolerance: the local error of a fifth-order step is ~ h^5.
  double h = std::min(length, 0.5 * std::pow(rtol, 0.2));
  elastica_rhs(run.piece, s, run.y.data(), k1.data(), run.Ns);
  long taken = 0;
  while (s < run.s_b) {
    if (++taken > run.max_steps) {
      run.error = fmt::format("Dormand-Prince: more than {} steps at s = {}", run.max_steps, s);
      return false;
    }
    double s_stop = run.s_b;
    if (run.shape.pending_before(run.s_b))
      s_stop = std::max((*run.shape.shape_s)[run.shape.next], s);
    bool last = false;
    if (s + h >= s_stop - 1e-14 * length) {
      h = s_stop - s;
      last = true;
    }
    if (h <= 0.0) {
      run.shape.emit(run.y.data());  // a shape point at the current position
      continue;
    }
    auto stage = [&](std::vector<double>& out,
                     std::initializer_list<std::pair<double, const std::vector<double>*>> terms) {
      for (int k = 0; k < dim; ++k) {
        double acc = run.y[k];
        for (const auto& [a, kv] : terms) acc += h * a * (*kv)[k];
        out[k] = acc;
      }
    };
    stage(tmp, {{a21, &k1}});
    elastica_rhs(run.piece, s + c2 * h, tmp.data(), k2.data(), run.Ns);
    stage(tmp, {{a31, &k1}, {a32, &k2}});
    elastica_rhs(run.piece, s + c3 * h, tmp.data(), k3.data(), run.Ns);
    stage(tmp, {{a41, &k1}, {a42, &k2}, {a43, &k3}});
    elastica_rhs(run.piece, s + c4 * h, tmp.data(), k4.data(), run.Ns);
    stage(tmp, {{a51, &k1}, {a52, &k2}, {a53, &k3}, {a54, &k4}});
    elastica_rhs(run.piece, s + c5 * h, tmp.data(), k5.data(), run.Ns);
    stage(tmp, {{a61, &k1}, {a62, &k2}, {a63, &k3}, {a64, &k4}, {a65, &k5}});
    elastica_rhs(run.piece, s + h, tmp.data(), k6.data(), run.Ns);
    stage(y_new, {{b1, &k1}, {b3, &k3}, {b4, &k4}, {b5, &k5}, {b6, &k6}});
    elastica_rhs(run.piece, s + h, y_new.data(), k7.data(), run.Ns);
    double err = 0.0;
    for (int k = 0; k < dim; ++k) {
      const double e =
          h * (e1 * k1[k] + e3 * k3[k] + e4 * k4[k] + e5 * k5[k] + e6 * k6[k] + e7 * k7[k]);
      const double scale = atol + rtol * std::max(std::abs(run.y[k]), std::abs(y_new[k]));
      err = std::max(err, std::abs(e) / scale);
    }
    if (!std::isfinite(err)) {
      run.error = fmt::format("Dormand-Prince: non-finite state at s = {}", s);
      return false;
    }
    if (err <= 1.0) {
      const double s_end = last ? s_stop : s + h;
      if (run.observer != nullptr) {
        run.observer->accepted_step(
            run.piece, s, run.y.data(), k1.data(), s_end, y_new.data(), k7.data());
      }
      s = s_end;
      run.y.swap(y_new);
      k1.swap(k7);
      if (last && s_stop < run.s_b && run.shape.shape != nullptr) run.shape.emit(run.y.data());
      if (last && s_stop >= run.s_b) break;
    }
    h *= std::clamp(0.9 * std::pow(std::max(err, 1e-10), -0.2), 0.2, 5.0);
  }
  run.steps += taken;
  return true;
}

}  // namespace flexure
