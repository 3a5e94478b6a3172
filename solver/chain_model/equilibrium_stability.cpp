#include "flexure/solver/chain_model/equilibrium_stability.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <variant>

namespace flexure {
namespace {

// Arc length of the far end of every segment (node k + 1).
std::vector<double> segment_ends(const SegmentChain& chain) {
  std::vector<double> ends;
  double s = 0.0;
  for (const Segment& segment : chain.segments) {
    s += std::visit([](const auto& seg) { return seg.length; }, segment);
    ends.push_back(s);
  }
  return ends;
}

}  // namespace

StabilityVerdict equilibrium_stability(const SegmentChain& chain,
                                       const std::vector<ShapePoint>& shape) {
  StabilityVerdict verdict;
  if (chain.end != EndCondition::kFree || chain.tip_load.follower != 0.0) {
    verdict.message = "stability is checked for a free end with dead loads only";
    return verdict;
  }
  if (shape.size() < 2) {
    verdict.message = "no shape to check";
    return verdict;
  }
  const std::vector<double> ends = segment_ends(chain);
  const double total = ends.back();
  double EI_min = HUGE_VAL;
  for (const Segment& segment : chain.segments) {
    if (const auto* f = std::get_if<FlexibleSegment>(&segment)) {
      EI_min = std::min(EI_min,
                        f->EI_profile.empty()
                            ? f->EI
                            : *std::min_element(f->EI_profile.begin(), f->EI_profile.end()));
    }
  }
  if (!std::isfinite(EI_min)) {
    verdict.message = "no flexible segment";
    return verdict;
  }
  const double eps = 1e-6 * EI_min / (total * total);

  // Tridiagonal K + eps M over the degrees of freedom eta_1..; dof -1 is the clamp (eta = 0).
  std::vector<double> diag, off;  // off[i] couples dof i and i + 1
  int dof = -1;
  auto add_diag = [&](int d, double v) {
    if (d >= 0) diag[static_cast<std::size_t>(d)] += v;
  };
  for (std::size_t j = 0; j + 1 < shape.size(); ++j) {
    const ShapePoint& a = shape[j];
    const ShapePoint& b = shape[j + 1];
    const double h = b.s - a.s;
    if (!(h > 0.0)) continue;
    const double mid = 0.5 * (a.s + b.s);
    const std::size_t segment = static_cast<std::size_t>(
        std::min<std::ptrdiff_t>(std::upper_bound(ends.begin(), ends.end(), mid) - ends.begin(),
                                 static_cast<std::ptrdiff_t>(ends.size()) - 1));
    // Dead forces applied beyond mid: the tip force and the loads at nodes k with s_k > mid.
    double Nx = chain.tip_load.Fx, Ny = chain.tip_load.Fy;
    for (const NodeLoad& load : chain.node_loads) {
      if (ends[static_cast<std::size_t>(load.node - 1)] > mid) {
        Nx += load.Fx;
        Ny += load.Fy;
      }
    }
    const double theta = 0.5 * (a.theta + b.theta);
    const double axial = Nx * std::cos(theta) + Ny * std::sin(theta);
    const auto* flexible = std::get_if<FlexibleSegment>(&chain.segments[segment]);
    if (flexible == nullptr) {
      // Rigid: eta constant over the link; only the axial term.
      if (dof < 0) continue;
      add_diag(dof, h * (axial + eps));
      continue;
    }
    const double local = mid - (segment == 0 ? 0.0 : ends[segment - 1]);
    const double k = flexible->EI_at(local) / h;
    const int next = dof + 1;
    diag.push_back(0.0);
    off.push_back(0.0);
    add_diag(dof, k + 0.5 * h * (axial + eps));
    add_diag(next, k + 0.5 * h * (axial + eps));
    if (dof >= 0) off[static_cast<std::size_t>(dof)] = -k;
    dof = next;
  }
  // L D L^T of the symmetric tridiagonal matrix; negative pivots = negative eigenvalues.
  double pivot = 0.0;
  for (std::size_t i = 0; i < diag.size(); ++i) {
    pivot = i == 0 ? diag[0] : diag[i] - off[i - 1] * off[i - 1] / pivot;
    if (pivot < 0.0) ++verdict.unstable_directions;
    if (pivot == 0.0) pivot = 1e-300;
  }
  verdict.kind = verdict.unstable_directions == 0 ? StabilityVerdict::Kind::kStable
                                                  : StabilityVerdict::Kind::kUnstable;
  verdict.message =
      verdict.unstable_directions == 0
          ? "stable: the second variation of the potential energy is positive definite"
          : fmt::format(
                "unstable: the second variation of the potential energy has {} negative "
                "direction{} (a buckled state that the load path from zero does not reach "
                "without passing a limit point)",
                verdict.unstable_directions,
                verdict.unstable_directions == 1 ? "" : "s");
  return verdict;
}

}  // namespace flexure
