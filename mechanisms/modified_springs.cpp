#include "mechanisms/modified_springs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "mechanisms/mechanism_prbm.h"
#include "mechanisms/modified_designs.h"
#include "solver/common/errors.h"

namespace flexure::mechanism {
namespace {

// Strain energy and end-to-end rotation of every flexible segment of one solved nondimensional
// chain (the statics of exact_segment_state: m(s) = m0 + (Nx y - Ny x) L, no node loads).
void add_chain(const MechanismDesign& design,
               const SegmentChain& chain,
               const std::vector<double>& unknowns,
               const std::vector<int>& pivots,
               double m0,
               double Nx,
               double Ny,
               double L,
               double EI_scale,
               int shape_points,
               std::array<std::optional<double>, 3>& ratio) {
  ShootingSolver::Options o;
  o.backend = ElasticaIntegrator::Backend::kDormandPrince;
  o.shape_points = shape_points;
  const ShootingResult r = ShootingSolver(o).solve_from(chain, unknowns);
  if (!r.converged || r.shape.size() < 2) {
    throw NoConvergence("re-solving the exact point for its shape failed: " + r.message);
  }
  auto at = [&](double s) {  // shape point interpolated at arc length s
    auto it = std::lower_bound(
        r.shape.begin(), r.shape.end(), s, [](const ShapePoint& q, double v) { return q.s < v; });
    if (it == r.shape.begin()) return *it;
    if (it == r.shape.end()) return r.shape.back();
    const ShapePoint &b = *it, &a = *(it - 1);
    const double t = (s - a.s) / (b.s - a.s);
    return ShapePoint{
        s, a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.theta + t * (b.theta - a.theta)};
  };
  auto moment = [&](const ShapePoint& q) { return m0 + (Nx * q.y - Ny * q.x) * L; };
  double s0 = 0.0;
  for (std::size_t j = 0; j < chain.segments.size(); ++j) {
    const auto& seg = chain.segments[j];
    const auto* f = std::get_if<FlexibleSegment>(&seg);
    const double len = f != nullptr ? f->length : std::get<RigidSegment>(seg).length;
    const int pivot = j < pivots.size() ? pivots[j] : 0;
    if (f != nullptr && pivot > 0) {
      std::vector<ShapePoint> q{at(s0)};
      for (const ShapePoint& p : r.shape) {
        if (p.s > s0 && p.s < s0 + len) q.push_back(p);
      }
      q.push_back(at(s0 + len));
      double U = 0.0;  // integral m^2 ds (trapezoidal), N^2 m^2 x (nondimensional length)
      for (std::size_t k = 1; k < q.size(); ++k) {
        const double ma = moment(q[k - 1]), mb = moment(q[k]);
        U += 0.5 * (q[k].s - q[k - 1].s) * (ma * ma + mb * mb);
      }
      const double EI = f->EI * EI_scale, length = len * L;
      U *= L / (2.0 * EI);
      const double dtheta = q.back().theta - q.front().theta;
      ratio[pivot - 1] = 2.0 * U / (dtheta * dtheta) / (EI / length);
    }
    s0 += len;
  }
  (void)design;
}

}  // namespace

std::array<std::optional<double>, 3> equivalent_spring_ratios(const MechanismDesign& design,
                                                              const ExactPoint& point,
                                                              int shape_points) {
  if (!point.converged) throw InvalidInput("equivalent_spring_ratios needs a converged point");
  const PhysicalChain pc = physical_chain(design);
  std::array<std::optional<double>, 3> ratio;
  add_chain(design,
            point.chain,
            point.unknowns,
            pc.flexible_pivot,
            point.m0,
            point.Nx,
            point.Ny,
            point.length_scale,
            point.EI_scale,
            shape_points,
            ratio);
  if (!point.coupler_chain.segments.empty()) {
    add_chain(design,
              point.coupler_chain,
              point.coupler_unknowns,
              pc.coupler_flexible_pivot,
              point.coupler_m0,
              point.Nx,
              point.Ny,
              point.length_scale,
              point.EI_scale,
              shape_points,
              ratio);
  }
  return ratio;
}

SpringRuleComparison compare_spring_rules(const MechanismDesign& design, int points) {
  SpringRuleComparison c;
  c.name = design.name;
  MechanismDesign d = design;
  d.finalise();
  const std::vector<double> dx = stroke_displacements(d, points);
  const ExactStrokeResult exact = exact_stroke(d, dx);
  if (!exact.converged) {
    c.message = exact.message;
    return c;
  }
  double mean_exact = 0.0;
  for (const ExactPoint& p : exact.points) mean_exact += p.force / points;
  const SpringRule rules[3] = {SpringRule::kPureBending, SpringRule::kTable2, SpringRule::kTable5};
  std::vector<double> F_pure;
  for (int r = 0; r < 3; ++r) {
    apply_spring_rule(d, rules[r]);
    const PrbmStrokeResult prbm = prbm_stroke(d, points);
    if (r == 0) F_pure = prbm.force;
    for (int k = 0; k < points; ++k) {
      const double Fe = exact.points[k].force;
      c.max_force_error[r] =
          std::max(c.max_force_error[r], std::abs(prbm.force[k] - Fe) / std::abs(Fe));
    }
    c.mean_force_ratio[r] = prbm.mean_force / mean_exact;
  }
  // The PRBM force is linear in the spring constants: F_prbm(c EI/L) = c F_prbm(EI/L).
  double num = 0.0, den = 0.0;
  for (int k = 0; k < points; ++k) {
    num += exact.points[k].force * F_pure[k];
    den += F_pure[k] * F_pure[k];
  }
  c.fitted_factor = num / den;
  for (int k = 0; k < points; ++k) {
    const double Fe = exact.points[k].force;
    c.fitted_max_error =
        std::max(c.fitted_max_error, std::abs(c.fitted_factor * F_pure[k] - Fe) / std::abs(Fe));
  }
  c.k_ratio_start = equivalent_spring_ratios(design, exact.points.front());
  c.k_ratio_end = equivalent_spring_ratios(design, exact.points.back());
  c.converged = true;
  c.message = exact.message;
  return c;
}

}  // namespace flexure::mechanism
