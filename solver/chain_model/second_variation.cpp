#include "flexure/solver/chain_model/second_variation.h"

#include <fmt/format.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

// Inertia of the constrained pencil with reusable work arrays (the eigenvalue search evaluates it
// a few dozen times on the same pencil).
class InertiaEvaluator {
 public:
  explicit InertiaEvaluator(const DiscreteSecondVariation& q) : q_(q) {
    const std::size_t n = q.bending_diag.size();
    if (q.bending_off.size() + 1 != std::max<std::size_t>(n, 1) || q.axial.size() != n ||
        q.constraints.size() > 2 ||
        std::any_of(q.constraints.begin(), q.constraints.end(), [n](const auto& row) {
          return row.size() != n;
        })) {
      throw InvalidInput(fmt::format(
          "inconsistent discrete second variation: {} diagonal, {} off-diagonal, {} axial "
          "entries, {} constraint rows (at most 2, each of the size of the diagonal)",
          n,
          q.bending_off.size(),
          q.axial.size(),
          q.constraints.size()));
    }
    inv_d_.resize(n);
    l_.resize(n);
    x0_.resize(n);
    x1_.resize(n);
  }

  PencilInertia operator()(double lambda) {
    PencilInertia out;
    const std::size_t n = q_.bending_diag.size();
    if (n == 0) return out;
    const double* B = q_.bending_diag.data();
    const double* b = q_.bending_off.data();
    const double* W = q_.axial.data();
    const double sigma = 1.0 / (1.0 - lambda);
    // L D L^T of A(sigma) = B + sigma W, with the pivots' sigma-derivatives: d_i = a_i -
    // b_{i-1}^2 / d_{i-1}, so d_i' = W_ii + (b_{i-1} / d_{i-1})^2 d_{i-1}' (B, b constant). A
    // tridiagonal L D L^T counts the negative eigenvalues of a matrix within rounding of A
    // (Kahan 1966), so no pivoting; a pivot that is exactly zero is replaced by the smallest
    // negative number (an eigenvalue at sigma is counted as below it).
    int negative = 0;
    double slope = 0.0;
    double inv = 0.0, dd = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      double a = B[i] + sigma * W[i];
      double da = W[i];
      if (i > 0) {
        const double l = b[i - 1] * inv;
        l_[i - 1] = l;
        a -= l * b[i - 1];
        da += l * l * dd;
      }
      if (a == 0.0) a = -std::numeric_limits<double>::min();
      inv = 1.0 / a;
      dd = da;
      inv_d_[i] = inv;
      negative += a < 0.0 ? 1 : 0;
      slope += da * inv;
    }
    out.negative_A = negative;
    out.log_det_slope = slope;
    const std::size_t m = q_.constraints.size();
    if (m == 0) {
      out.count = out.negative_A;
      return out;
    }
    // X = A^{-1} C^T (both rows in one sweep), S = C X, dS/dsigma = -X^T W X.
    const double* c0 = q_.constraints[0].data();
    const double* c1 = m > 1 ? q_.constraints[1].data() : c0;
    double* x0 = x0_.data();
    double* x1 = x1_.data();
    x0[0] = c0[0];
    x1[0] = c1[0];
    for (std::size_t i = 1; i < n; ++i) {
      x0[i] = c0[i] - l_[i - 1] * x0[i - 1];
      x1[i] = c1[i] - l_[i - 1] * x1[i - 1];
    }
    x0[n - 1] *= inv_d_[n - 1];
    x1[n - 1] *= inv_d_[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) {
      x0[i] = x0[i] * inv_d_[i] - l_[i] * x0[i + 1];
      x1[i] = x1[i] * inv_d_[i] - l_[i] * x1[i + 1];
    }
    // The compliance of an extensible chain's constraints (second_variation.h): S + D / sigma,
    // whose sigma-derivative adds -D / sigma^2.
    const std::array<double, 3>& D = q_.compliance;
    const double inv_sigma = 1.0 / sigma;
    double s00 = D[0] * inv_sigma, s01 = D[1] * inv_sigma, s11 = D[2] * inv_sigma;
    double d00 = -D[0] * inv_sigma * inv_sigma, d01 = -D[1] * inv_sigma * inv_sigma,
           d11 = -D[2] * inv_sigma * inv_sigma;
    for (std::size_t i = 0; i < n; ++i) {
      s00 += c0[i] * x0[i];
      s01 += c0[i] * x1[i];
      s11 += c1[i] * x1[i];
      d00 -= W[i] * x0[i] * x0[i];
      d01 -= W[i] * x0[i] * x1[i];
      d11 -= W[i] * x1[i] * x1[i];
    }
    if (m == 1) {
      out.negative_S = s00 < 0.0 ? 1 : 0;
      out.zero_S = s00 == 0.0 ? 1 : 0;
      out.log_det_slope += d00 / s00;
    } else {
      const double det = s00 * s11 - s01 * s01;
      const double trace = s00 + s11;
      if (det < 0.0) {
        out.negative_S = 1;
      } else if (det > 0.0) {
        out.negative_S = trace < 0.0 ? 2 : 0;
      } else {
        out.zero_S = 1;
        out.negative_S = trace < 0.0 ? 1 : 0;
      }
      out.log_det_slope += (s11 * d00 - 2.0 * s01 * d01 + s00 * d11) / det;
    }
    out.count = out.negative_A - out.negative_S - out.zero_S;
    return out;
  }

 private:
  const DiscreteSecondVariation& q_;
  std::vector<double> inv_d_, l_, x0_, x1_;
};

}  // namespace

PencilInertia constrained_inertia(const DiscreteSecondVariation& q, double lambda) {
  InertiaEvaluator evaluate(q);
  return evaluate(lambda);
}

PencilEigenvalue constrained_eigenvalue(const DiscreteSecondVariation& q,
                                        int k,
                                        double tolerance,
                                        const double* guess,
                                        double guess_radius) {
  PencilEigenvalue result;
  if (q.size() == 0 || !(q.compression_bound > 0.0) || k < 1) return result;
  InertiaEvaluator evaluate(q);
  const double gamma = q.compression_bound;
  // Below 1 - Gamma no eigenvalue (second_variation.h); a little lower for rounding.
  double lo = 1.0 - gamma * (1.0 + 1e-9) - 1e-12;
  int count_lo = 0;
  double hi = 1.0;
  int count_hi = -1;  // not yet known
  auto record = [&](double x, const PencilInertia& at) {
    ++result.evaluations;
    if (at.count >= k) {
      if (count_hi < 0 || x < hi) {
        hi = x;
        count_hi = at.count;
      }
    } else if (x > lo) {
      lo = x;
      count_lo = at.count;
    }
  };
  double x = 1.0 - 0.5 * gamma;
  PencilInertia at;
  if (guess != nullptr && *guess > lo && *guess < 1.0) {
    // Probe outwards from the guess, by guess_radius and then 4 times further each time, until the
    // eigenvalue is bracketed; Newton then starts from the guess.
    x = *guess;
    at = evaluate(x);
    record(x, at);
    double step = guess_radius > 0.0 ? guess_radius : 1e-3 * std::max(1.0, std::fabs(x));
    double from = x;
    for (int probe = 0; probe < 6 && (count_hi < 0 || count_lo != k - 1 || count_hi != k);
         ++probe) {
      const bool left = count_hi >= 0 && hi <= from;
      double y = left ? from - step : from + step;
      if (left && y <= lo) y = 0.5 * (lo + from);
      if (!left && y >= 1.0) y = 1.0 - 0.25 * (1.0 - from);
      const PencilInertia at_y = evaluate(y);
      record(y, at_y);
      if ((left && at_y.count < k) || (!left && at_y.count >= k)) break;
      from = y;
      step *= 4.0;
    }
  } else {
    at = evaluate(x);
    record(x, at);
  }
  // Without an upper end yet: move towards 1 (sigma doubled twice per step) until k eigenvalues
  // lie below; none within 1e-14 of 1 means fewer than k exist.
  while (count_hi < 0) {
    if (1.0 - lo < 1e-14) return result;
    x = 1.0 - 0.25 * (1.0 - lo);
    at = evaluate(x);
    record(x, at);
  }
  // The requested tolerance, but not below the rounding noise of the inertia near the eigenvalue:
  // A(sigma) = B + sigma W is singular there through the cancellation of B's smallest eigenvalue
  // (about EI/L / n) against sigma W, B's largest being about 4 n EI/L; rounding perturbs sigma by
  // eps n^2 at worst, by far less in practice (margins at n = 260, 516 and 1028 agree to 2e-11),
  // so lambda = 1 - 1/sigma is taken as known to 1e-17 n^2 (1 - lambda).
  const double n2 = static_cast<double>(q.size()) * static_cast<double>(q.size());
  auto width_tolerance = [&](double v) {
    return std::max(tolerance * std::max(1.0, std::fabs(v)), 1e-17 * n2 * (1.0 - v));
  };
  double step_two_ago = HUGE_VAL, step_one_ago = HUGE_VAL;
  for (int iteration = 0; iteration < 400; ++iteration) {
    const double width = hi - lo;
    if (width <= width_tolerance(hi)) {
      result.value = 0.5 * (lo + hi);
      result.exists = true;
      return result;
    }
    // Newton in sigma once [lo, hi] holds the k-th eigenvalue alone, while its step stays inside
    // the bracket and is at most half the step before the last (as in Numerical Recipes'
    // rtsafe); bisection in lambda otherwise.
    double next = 0.5 * (lo + hi);
    bool newton = false;
    if (count_lo == k - 1 && count_hi == k && std::isfinite(at.log_det_slope) &&
        at.log_det_slope != 0.0) {
      const double sigma = 1.0 / (1.0 - x);
      const double sigma_next = sigma - 1.0 / at.log_det_slope;
      if (sigma_next > 0.0) {
        const double candidate = 1.0 - 1.0 / sigma_next;
        if (candidate > lo && candidate < hi && std::fabs(candidate - x) <= 0.5 * step_two_ago) {
          next = candidate;
          newton = true;
        }
      }
    }
    if (newton && std::fabs(next - x) <= 0.5 * width_tolerance(next)) {
      result.value = next;
      result.exists = true;
      return result;
    }
    step_two_ago = step_one_ago;
    step_one_ago = std::fabs(next - x);
    x = next;
    at = evaluate(x);
    record(x, at);
  }
  result.value = 0.5 * (lo + hi);
  result.exists = true;
  return result;
}

bool solve_bordered(const DiscreteSecondVariation& q,
                    double bending_factor,
                    double axial_factor,
                    const std::vector<double>& rhs,
                    std::vector<double>& x) {
  const int n = q.size();
  const int m = static_cast<int>(q.constraints.size());
  if (static_cast<int>(rhs.size()) != n) {
    throw InvalidInput(fmt::format(
        "bordered solve: right-hand side of {} entries for {} unknowns", rhs.size(), n));
  }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(3 * n + 2 * m * n));
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, bending_factor * q.bending_diag[i] + axial_factor * q.axial[i]);
    if (i + 1 < n) {
      entries.emplace_back(i, i + 1, bending_factor * q.bending_off[i]);
      entries.emplace_back(i + 1, i, bending_factor * q.bending_off[i]);
    }
  }
  for (int a = 0; a < m; ++a) {
    for (int i = 0; i < n; ++i) {
      const double c = q.constraints[a][i];
      if (c == 0.0) continue;
      entries.emplace_back(n + a, i, c);
      entries.emplace_back(i, n + a, c);
    }
  }
  // An extensible chain's compliant constraints (second_variation.h): the axial factor scales the
  // condensed term C^T D^{-1} C with W, so the border's block is -D / axial_factor.
  const std::array<double, 3>& D = q.compliance;
  if (m > 0 && (D[0] != 0.0 || D[1] != 0.0 || D[2] != 0.0)) {
    if (axial_factor == 0.0) return false;
    entries.emplace_back(n, n, -D[0] / axial_factor);
    if (m > 1) {
      entries.emplace_back(n, n + 1, -D[1] / axial_factor);
      entries.emplace_back(n + 1, n, -D[1] / axial_factor);
      entries.emplace_back(n + 1, n + 1, -D[2] / axial_factor);
    }
  }
  Eigen::SparseMatrix<double> K(n + m, n + m);
  K.setFromTriplets(entries.begin(), entries.end());
  K.makeCompressed();
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(K);
  if (lu.info() != Eigen::Success) return false;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n + m);
  for (int i = 0; i < n; ++i) b[i] = rhs[i];
  const Eigen::VectorXd solution = lu.solve(b);
  if (lu.info() != Eigen::Success || !solution.allFinite()) return false;
  x.assign(solution.data(), solution.data() + n);
  return true;
}

std::vector<double> constrained_eigenvector(const DiscreteSecondVariation& q, double lambda) {
  if (!(lambda < 1.0)) {
    throw InvalidInput(fmt::format(
        "constrained_eigenvector: lambda = {} must be below 1 (the eigenvalues of the pencil "
        "below 1 have eigenvectors)",
        lambda));
  }
  const int n = q.size();
  if (n == 0) throw InvalidInput("constrained_eigenvector: no degrees of freedom");
  // B-products and norms (B tridiagonal).
  auto times_B = [&](const std::vector<double>& v) {
    std::vector<double> out(n);
    for (int i = 0; i < n; ++i) {
      double sum = q.bending_diag[i] * v[i];
      if (i > 0) sum += q.bending_off[i - 1] * v[i - 1];
      if (i + 1 < n) sum += q.bending_off[i] * v[i + 1];
      out[i] = sum;
    }
    return out;
  };
  auto normalise = [&](std::vector<double>& v) {
    const std::vector<double> Bv = times_B(v);
    double norm2 = 0.0;
    for (int i = 0; i < n; ++i) norm2 += v[i] * Bv[i];
    if (!(norm2 > 0.0) || !std::isfinite(norm2)) return false;
    const double scale = 1.0 / std::sqrt(norm2);
    std::size_t largest = 0;
    for (int i = 0; i < n; ++i) {
      if (std::fabs(v[i]) > std::fabs(v[largest])) largest = static_cast<std::size_t>(i);
    }
    const double sign = v[largest] < 0.0 ? -1.0 : 1.0;
    for (double& value : v) value *= sign * scale;
    return true;
  };
  const double sigma = 1.0 / (1.0 - lambda);
  const double shifted = sigma * (1.0 + 1e-9);
  // A smooth start with a component along every low mode: eta_i = i + 1 (a ramp), made
  // admissible by the first solve.
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = 1.0 + i;
  std::vector<double> next;
  for (int iteration = 0; iteration < 30; ++iteration) {
    // (B + sigma' W) y = B v on ker C: amplifies the eigenvector at sigma by 1 / (1 - sigma' /
    // sigma) against the others.
    if (!solve_bordered(q, 1.0, shifted, times_B(v), next) || !normalise(next)) {
      throw NoConvergence(fmt::format(
          "constrained_eigenvector: the bordered matrix at lambda = {:.12g} is singular", lambda));
    }
    double change = 0.0, size = 0.0;
    for (int i = 0; i < n; ++i) {
      change = std::max(change, std::fabs(next[i] - v[i]));
      size = std::max(size, std::fabs(next[i]));
    }
    v.swap(next);
    if (iteration > 0 && change <= 1e-10 * size) return v;
  }
  throw NoConvergence(fmt::format(
      "constrained_eigenvector: inverse iteration at lambda = {:.12g} did not settle (a multiple "
      "eigenvalue, or not an eigenvalue of the pencil)",
      lambda));
}

std::vector<std::array<double, 2>> independent_row_combinations(
    const std::vector<std::vector<double>>& raw_rows,
    const std::vector<double>& weight,
    double total) {
  const std::size_t m = raw_rows.size();
  std::vector<std::array<double, 2>> keep;
  if (m == 0 || weight.empty()) return keep;
  if (m > 2) throw InvalidInput("at most two tip-coordinate constraint rows (x and y)");
  double G[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t b = 0; b < m; ++b) {
      for (std::size_t i = 0; i < weight.size(); ++i) {
        if (weight[i] > 0.0) G[a][b] += raw_rows[a][i] * raw_rows[b][i] / weight[i];
      }
    }
  }
  const double threshold = 1e-20 * total;
  if (m == 1) {
    if (G[0][0] > threshold) keep.push_back({1.0 / std::sqrt(G[0][0]), 0.0});
    return keep;
  }
  // Symmetric 2 x 2 eigenvectors.
  const double mean = 0.5 * (G[0][0] + G[1][1]);
  const double radius = std::hypot(0.5 * (G[0][0] - G[1][1]), G[0][1]);
  for (const double mu : {mean + radius, mean - radius}) {
    if (!(mu > threshold)) continue;
    // (G - mu I) v = 0: v = (G01, mu - G00) or (mu - G11, G01), the better conditioned.
    double vx = G[0][1], vy = mu - G[0][0];
    if (std::hypot(mu - G[1][1], G[0][1]) > std::hypot(vx, vy)) {
      vx = mu - G[1][1];
      vy = G[0][1];
    }
    const double norm = std::hypot(vx, vy);
    if (!(norm > 0.0)) {
      vx = keep.empty() ? 1.0 : 0.0;
      vy = keep.empty() ? 0.0 : 1.0;
    } else {
      vx /= norm;
      vy /= norm;
    }
    const double scale = 1.0 / std::sqrt(mu);
    keep.push_back({vx * scale, vy * scale});
  }
  return keep;
}

std::vector<std::vector<double>> combine_rows(
    const std::vector<std::vector<double>>& raw_rows,
    const std::vector<std::array<double, 2>>& combinations) {
  std::vector<std::vector<double>> rows;
  const std::size_t n = raw_rows.empty() ? 0 : raw_rows.front().size();
  for (const std::array<double, 2>& v : combinations) {
    std::vector<double> row(n, 0.0);
    for (std::size_t a = 0; a < raw_rows.size(); ++a) {
      for (std::size_t i = 0; i < n; ++i) row[i] += v[a] * raw_rows[a][i];
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

double extrapolated_eigenvalue(const std::vector<const DiscreteSecondVariation*>& levels,
                               int k,
                               double tolerance,
                               double* error,
                               double* fine_value) {
  if (error != nullptr) *error = HUGE_VAL;
  const std::size_t n = levels.size();
  std::vector<double> values(n);  // fine to coarse
  std::vector<bool> found(n, false);
  bool have_guess = false;
  double guess = 0.0, radius = 0.0;
  for (std::size_t level = n; level-- > 0;) {
    const PencilEigenvalue e =
        constrained_eigenvalue(*levels[level], k, tolerance, have_guess ? &guess : nullptr, radius);
    if (!e.exists) {
      have_guess = false;  // a coarse grid may lack an eigenvalue close to 1
      continue;
    }
    values[level] = e.value;
    found[level] = true;
    if (level + 1 < n && found[level + 1]) {
      const double change = e.value - values[level + 1];
      guess = e.value + change / 4.0;  // Richardson's prediction of the next finer grid
      radius = 0.1 * std::fabs(change) + 1e-12;
    } else {
      guess = e.value;
      radius = 0.05 * std::max(1.0, std::fabs(e.value));
    }
    have_guess = true;
  }
  if (!found[0]) {
    if (error != nullptr) *error = 0.0;
    if (fine_value != nullptr) *fine_value = 1.0;
    return 1.0;
  }
  if (fine_value != nullptr) *fine_value = values[0];
  if (n == 1 || !found[1]) return std::min(1.0, values[0]);
  const double r_fine = (4.0 * values[0] - values[1]) / 3.0;
  if (n == 2 || !found[2]) {
    if (error != nullptr) *error = std::fabs(r_fine - values[0]);
    return std::min(1.0, r_fine);
  }
  const double r_coarse = (4.0 * values[1] - values[2]) / 3.0;
  const double romberg = (16.0 * r_fine - r_coarse) / 15.0;
  if (error != nullptr) *error = std::fabs(romberg - r_fine);
  return std::min(1.0, romberg);
}

}  // namespace flexure
