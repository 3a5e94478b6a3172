#include "flexure/mechanisms/mechanism_second_variation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

// One grid before its constraint rows are combined (as the chain's assembly,
// solver/chain_model/equilibrium_stability.cpp).
struct Grid {
  DiscreteSecondVariation q;
  std::vector<double> weight;                 // lumped weight of int eta^2 at each dof
  std::vector<std::vector<double>> raw_rows;  // sin(theta) row if x held, cos(theta) if y held
};

// Largest stride every flexible piece's element count allows (1, 2 or 4).
int largest_stride(const MechanismPath& path) {
  int stride = 4;
  for (const PathPiece& p : path.pieces) {
    if (p.EI <= 0.0) continue;
    const std::size_t n = p.points.size() - 1;
    while (stride > 1 && n % static_cast<std::size_t>(stride) != 0) stride /= 2;
  }
  return stride;
}

void check_path(const MechanismPath& path) {
  if (path.pieces.empty()) throw InvalidInput("the mechanism's path has no piece");
  require_finite(path.Nx, "path force Nx");
  require_finite(path.Ny, "path force Ny");
  for (std::size_t i = 0; i < path.pieces.size(); ++i) {
    const PathPiece& p = path.pieces[i];
    const bool flexible = p.EI > 0.0;
    if (!(p.length > 0.0) || !std::isfinite(p.length) || !std::isfinite(p.EI) || p.EI < 0.0 ||
        p.points.size() < 2 || (!flexible && p.points.size() != 2)) {
      throw InvalidInput(fmt::format(
          "path piece {}: length {} (> 0), EI {} (>= 0) and {} points (2 for a rigid link, at "
          "least 2 for a flexure)",
          i + 1,
          p.length,
          p.EI,
          p.points.size()));
    }
    for (const auto& q : p.points) {
      if (!std::isfinite(q[0]) || !std::isfinite(q[1])) {
        throw InvalidInput(fmt::format("path piece {} has a point that is not finite", i + 1));
      }
    }
  }
}

Grid assemble(const MechanismPath& path, int stride) {
  Grid g;
  const std::size_t rows = (path.hold_x ? 1 : 0) + (path.hold_y ? 1 : 0);
  g.raw_rows.resize(rows);
  int dof = -1;  // the dof whose rotation the current point carries (-1: the clamp, eta = 0)
  auto add_dof = [&] {
    g.q.bending_diag.push_back(0.0);
    if (dof >= 0) g.q.bending_off.push_back(0.0);  // no coupling unless an element adds it
    g.q.axial.push_back(0.0);
    g.weight.push_back(0.0);
    for (std::vector<double>& row : g.raw_rows) row.push_back(0.0);
    ++dof;
  };
  // The axial term, weight and rows of a piece of length h along t, lumped onto dof d.
  auto lump = [&](int d, double h, double tx, double ty) {
    if (d < 0) return;
    const auto i = static_cast<std::size_t>(d);
    g.q.axial[i] += h * (path.Nx * tx + path.Ny * ty);
    g.weight[i] += h;
    std::size_t r = 0;
    if (path.hold_x) g.raw_rows[r++][i] += h * ty;  // int sin(theta) eta ds
    if (path.hold_y) g.raw_rows[r++][i] += h * tx;  // int cos(theta) eta ds
  };
  auto chord = [&](const std::array<double, 2>& a,
                   const std::array<double, 2>& b,
                   double h,
                   std::size_t piece) {
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double length = std::hypot(dx, dy);
    if (length > 1.05 * h + 1e-12 || !(length > 1e-6 * h)) {
      throw InvalidInput(fmt::format(
          "path piece {}: two points {:.9g} apart for an arc length of {:.9g} (not a shape of "
          "this path)",
          piece + 1,
          length,
          h));
    }
    return std::array<double, 2>{dx / length, dy / length};
  };
  for (std::size_t j = 0; j < path.pieces.size(); ++j) {
    const PathPiece& p = path.pieces[j];
    if (p.hinge) add_dof();  // an independent rotation from here on (a pinned root at j = 0)
    if (p.EI > 0.0) {
      const std::size_t n = p.points.size() - 1;
      const auto step = static_cast<std::size_t>(stride);
      for (std::size_t a = 0; a < n; a += step) {
        const std::size_t b = std::min(a + step, n);
        const double h = p.length * static_cast<double>(b - a) / static_cast<double>(n);
        const double k = p.EI / h;  // int EI eta'^2 with eta' = (eta_b - eta_a) / h
        const auto t = chord(p.points[a], p.points[b], h, j);
        const int near = dof;
        add_dof();
        const auto far = static_cast<std::size_t>(dof);
        g.q.bending_diag[far] += k;
        if (near >= 0) {
          g.q.bending_diag[static_cast<std::size_t>(near)] += k;
          g.q.bending_off[static_cast<std::size_t>(near)] -= k;
        }
        lump(near, 0.5 * h, t[0], t[1]);
        lump(dof, 0.5 * h, t[0], t[1]);
      }
    } else {
      // A rigid link: eta constant along it, its axial term and rows exact.
      const auto t = chord(p.points.front(), p.points.back(), p.length, j);
      lump(dof, p.length, t[0], t[1]);
    }
  }
  if (path.hold_theta && dof >= 0) {
    // eta(L) = 0: the last dof carries the tip's rotation.
    g.q.bending_diag.pop_back();
    if (!g.q.bending_off.empty()) g.q.bending_off.pop_back();
    g.q.axial.pop_back();
    g.weight.pop_back();
    for (std::vector<double>& row : g.raw_rows) row.pop_back();
  }
  return g;
}

double total_length(const MechanismPath& path) {
  double total = 0.0;
  for (const PathPiece& p : path.pieces) total += p.length;
  return total;
}

bool has_flexible(const MechanismPath& path) {
  return std::any_of(
      path.pieces.begin(), path.pieces.end(), [](const PathPiece& p) { return p.EI > 0.0; });
}

// Below this the energy is taken as unbounded below relative to B (a motion that bends nothing
// and is compressed): no lower bracket, no verdict.
constexpr double kLowestBracket = -1e9;

// Sets q.compression_bound so that 1 - bound is a lower bracket of every constrained eigenvalue:
// the count there is 0 (second_variation.h: lambda_1 >= 1 - compression_bound). False when no
// bracket above kLowestBracket exists.
bool bracket_from_below(DiscreteSecondVariation& q) {
  double lo = -1.0;
  while (constrained_count(q, lo) > 0) {
    lo *= 4.0;
    if (lo < kLowestBracket) return false;
  }
  q.compression_bound = 1.0 - lo;
  return true;
}

// The grids (fine, every 2nd, every 4th point as the pieces allow), bracketed.
struct Grids {
  std::vector<DiscreteSecondVariation> levels;
  double tolerance = 1e-12;
  bool bounded = true;

  // The k-th eigenvalue, extrapolated over the grids (second_variation.h,
  // extrapolated_eigenvalue).
  double eigenvalue(int k, double* error = nullptr, double* fine_value = nullptr) const {
    std::vector<const DiscreteSecondVariation*> q;
    q.reserve(levels.size());
    for (const auto& level : levels) q.push_back(&level);
    return extrapolated_eigenvalue(q, k, tolerance, error, fine_value);
  }
};

Grids make_grids(const MechanismPath& path, double eigenvalue_tolerance) {
  check_path(path);
  Grids grids;
  grids.tolerance = eigenvalue_tolerance;
  const int largest = largest_stride(path);
  std::vector<Grid> raw;
  for (int stride = 1; stride <= largest; stride *= 2) raw.push_back(assemble(path, stride));
  const auto combinations =
      independent_row_combinations(raw.front().raw_rows, raw.front().weight, total_length(path));
  for (Grid& g : raw) {
    g.q.constraints = combine_rows(g.raw_rows, combinations);
    grids.bounded = grids.bounded && bracket_from_below(g.q);
    grids.levels.push_back(std::move(g.q));
  }
  return grids;
}

}  // namespace

DiscreteSecondVariation path_second_variation(const MechanismPath& path, int stride) {
  check_path(path);
  if (stride != 1 && stride != 2 && stride != 4) {
    throw InvalidInput(fmt::format("stride must be 1, 2 or 4 (got {})", stride));
  }
  if (largest_stride(path) < stride) {
    throw InvalidInput(fmt::format(
        "stride {} needs element counts divisible by {} in every flexible piece", stride, stride));
  }
  Grid fine = assemble(path, 1);
  const auto combinations =
      independent_row_combinations(fine.raw_rows, fine.weight, total_length(path));
  Grid grid = stride == 1 ? std::move(fine) : assemble(path, stride);
  grid.q.constraints = combine_rows(grid.raw_rows, combinations);
  return grid.q;
}

PathVerdict path_stability(const MechanismPath& path,
                           const StabilityOptions& options,
                           std::string_view subject) {
  options.validate();
  PathVerdict v;
  if (!has_flexible(path)) {
    v.stability = not_checked_stability("the path has no flexible piece, so it cannot deflect");
    return v;
  }
  const Grids grids = make_grids(path, options.eigenvalue_tolerance);
  if (!grids.bounded) {
    v.stability = not_checked_stability(fmt::format(
        "the second variation is not bounded below relative to the bending stiffness (no "
        "eigenvalue bracket above {:g}): a compressed motion that bends no flexure",
        kLowestBracket));
    return v;
  }
  const DiscreteSecondVariation& fine = grids.levels.front();
  const double threshold = -options.critical_tolerance;
  const int below = constrained_count(fine, threshold);
  double fine_lowest = 1.0;
  const double lowest = grids.eigenvalue(1, &v.margin_error, &fine_lowest);
  int index = below;
  if (grids.levels.size() > 1) {
    // As for a chain (equilibrium_stability.cpp): the extrapolated eigenvalues decide only where
    // one lies within `band` of the threshold on the fine grid.
    const double band = std::max(0.05, 10.0 * std::fabs(fine_lowest - lowest));
    const bool near = below == 0 || constrained_count(fine, threshold - band) != below ||
                      constrained_count(fine, std::min(threshold + band, 0.5)) != below;
    if (near) {
      if (below >= 1 && (below == 1 ? lowest : grids.eigenvalue(below)) >= threshold) --index;
      if ((below == 0 ? lowest : grids.eigenvalue(below + 1)) < threshold) ++index;
    }
  }
  v.stability = classify_stability(index, lowest, options.critical_tolerance, subject);
  return v;
}

std::vector<double> path_eigenvalues(const MechanismPath& path,
                                     int count,
                                     const StabilityOptions& options) {
  options.validate();
  if (count < 0) throw InvalidInput(fmt::format("eigenvalue count must be >= 0 (got {})", count));
  if (!has_flexible(path)) throw InvalidInput("the path has no flexible piece");
  const Grids grids = make_grids(path, options.eigenvalue_tolerance);
  if (!grids.bounded) throw InvalidInput("the second variation is not bounded below");
  std::vector<double> values;
  for (int k = 1; k <= count; ++k) values.push_back(grids.eigenvalue(k));
  return values;
}

}  // namespace flexure::mechanism
