// The state of the flexible segments of a solved exact point (mechanism_exact.h): stresses, strain
// energy and rotations, either from one integration of the solution (exact_segment_state without
// a sample count: what `mechanism analyze` reports) or from its shape sampled at equally spaced arc
// lengths (the trapezoidal rule of exact_strain_energy, kept as an independent check).
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/segment_moments.h"

namespace flexure::mechanism {

namespace {

// One nondimensional chain of a solved point: the crank's chain, or the coupler's. Its internal
// force (tip load) is the point's (Nx, Ny) N in the chain's own frame (the coupler chain's frame
// is the root frame turned by pi about the slider: its tip load, the crank's push on the coupler,
// -N turned by pi, is +N there).
struct ChainPart {
  const SegmentChain& chain;
  const std::vector<double>& unknowns;
  const std::vector<int>& pivots;  // pivots[j]: the pivot of segment j (0: rigid or none)
  double m0;                       // root moment, N m
};

std::vector<ChainPart> chain_parts(const ExactPoint& point, const PhysicalChain& pc) {
  std::vector<ChainPart> parts{{point.chain, point.unknowns, pc.flexible_pivot, point.m0}};
  if (!point.coupler_chain.segments.empty()) {
    parts.push_back(
        {point.coupler_chain, point.coupler_unknowns, pc.coupler_flexible_pivot, point.coupler_m0});
  }
  return parts;
}

// Adds flexible segment j's strain energy U (J) to the total and, when it belongs to a pivot, its
// energy, rotation and largest stress (bending M c/I with the largest |moment| m_max N m, plus the
// axial N/A of the internal force N) to that pivot's.
void add_segment(const MechanismDesign& design,
                 const ChainPart& part,
                 std::size_t j,
                 double U,
                 double m_max,
                 double N,
                 double rotation,
                 ExactSegmentState& st) {
  st.strain_energy += U;
  const int pivot = j < part.pivots.size() ? part.pivots[j] : 0;
  if (pivot == 0) return;
  const JointDesign& jd = design.joints[pivot - 1];
  const Section section = jd.section();  // a rectangle: its area is known
  const double sigma = m_max * 0.5 * jd.thickness / section.second_moment() + N / *section.area();
  st.max_stress[pivot - 1] = std::max(st.max_stress[pivot - 1], sigma);
  st.pivot_strain_energy[pivot - 1] += U;
  st.pivot_rotation[pivot - 1] += rotation;
  st.has_pivot[pivot - 1] = true;
}

// Adds the stresses and strain energy of the flexible segments of one chain, re-solved from its
// unknowns for a shape of `shape_points` samples (the sampled check of add_chain_moments).
void accumulate_chain(const MechanismDesign& design,
                      const ChainPart& part,
                      const ExactPoint& point,
                      int shape_points,
                      ExactSegmentState& st) {
  const SegmentChain& chain = part.chain;
  const double m0 = part.m0, Nx = point.Nx, Ny = point.Ny, L = point.length_scale;
  ShootingSolver::Options o;
  o.shape_points = shape_points;
  const ShootingResult r = ShootingSolver(o).solve_from(chain, part.unknowns);
  if (!r.converged() || r.shape.size() < 2) {
    throw NoConvergence("re-solving the exact point for its shape failed: " + r.message);
  }
  auto moment = [&](const ShapePoint& q) { return m0 + (Nx * q.y - Ny * q.x) * L; };
  // Shape linearly interpolated at arc length s between the samples (segment ends).
  auto shape_at = [&](double s) {
    auto it = std::lower_bound(
        r.shape.begin(), r.shape.end(), s, [](const ShapePoint& q, double v) { return q.s < v; });
    if (it == r.shape.begin()) return *it;
    if (it == r.shape.end()) return r.shape.back();
    const ShapePoint& b = *it;
    const ShapePoint& a = *(it - 1);
    const double t = (s - a.s) / (b.s - a.s);
    return ShapePoint{
        s, a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.theta + t * (b.theta - a.theta)};
  };
  const double N = std::hypot(Nx, Ny);
  double s0 = 0.0;
  for (std::size_t j = 0; j < chain.segments.size(); ++j) {
    const auto& seg = chain.segments[j];
    const double len = std::holds_alternative<FlexibleSegment>(seg)
                           ? std::get<FlexibleSegment>(seg).length
                           : std::get<RigidSegment>(seg).length;
    if (const auto* f = std::get_if<FlexibleSegment>(&seg)) {
      const ShapePoint start = shape_at(s0), end = shape_at(s0 + len);
      std::vector<std::pair<double, double>> samples;  // (s, m)
      samples.emplace_back(s0, moment(start));
      for (const ShapePoint& q : r.shape) {
        if (q.s > s0 && q.s < s0 + len) samples.emplace_back(q.s, moment(q));
      }
      samples.emplace_back(s0 + len, moment(end));
      double U = 0.0, m_max = 0.0;
      for (std::size_t k = 0; k < samples.size(); ++k) {
        m_max = std::max(m_max, std::abs(samples[k].second));
        if (k > 0) {
          const double h = samples[k].first - samples[k - 1].first;
          U += 0.5 * h *
               (samples[k].second * samples[k].second +
                samples[k - 1].second * samples[k - 1].second);
        }
      }
      U *= L / (2.0 * f->EI * point.EI_scale);
      add_segment(design, part, j, U, m_max, N, end.theta - start.theta, st);
    }
    s0 += len;
  }
}

}  // namespace

ExactSegmentState exact_segment_state(const MechanismDesign& design,
                                      const ExactPoint& point,
                                      int shape_points) {
  if (!point.converged()) throw InvalidInput("exact_segment_state needs a converged point");
  const PhysicalChain pc = physical_chain(design);
  ExactSegmentState st;
  for (const ChainPart& part : chain_parts(point, pc)) {
    accumulate_chain(design, part, point, shape_points, st);
  }
  return st;
}

double exact_strain_energy(const MechanismDesign& design,
                           const ExactPoint& point,
                           int shape_points) {
  if (shape_points < 3) {
    throw InvalidInput(fmt::format("shape_points must be >= 3 (got {})", shape_points));
  }
  const double coarse = exact_segment_state(design, point, shape_points).strain_energy;
  const double fine = exact_segment_state(design, point, 2 * shape_points - 1).strain_energy;
  return (4.0 * fine - coarse) / 3.0;
}

namespace {

// Adds the stresses, strain energy and rotations of the flexible segments of one nondimensional
// chain from one integration of its solved unknowns (segment_moments.h): no Newton iteration when
// `unknowns` are complete (root loads and cut states), else one Newton solve from them to find the
// cut states. The tip load (Nx, Ny) N gives the axial stress, as above.
void add_chain_moments(const MechanismDesign& design,
                       const ChainPart& part,
                       const ExactPoint& point,
                       const ShootingSolver::Options& options,
                       ExactSegmentState& st) {
  const SegmentChain& chain = part.chain;
  const std::vector<double>& unknowns = part.unknowns;
  const ShootingProblem problem(chain, options.multiple_shooting);
  Eigen::VectorXd z = Eigen::Map<const Eigen::VectorXd>(unknowns.data(),
                                                        static_cast<Eigen::Index>(unknowns.size()));
  if (z.size() != problem.size()) {
    const ShootingResult r = ShootingSolver(options).solve_from(chain, unknowns);
    if (!r.converged()) {
      throw NoConvergence("completing the exact point's unknowns failed: " + r.message);
    }
    z = Eigen::Map<const Eigen::VectorXd>(r.unknowns.data(),
                                          static_cast<Eigen::Index>(r.unknowns.size()));
  }
  ElasticaIntegrator integrator(options.integrator_options());
  std::vector<SegmentMoments> moments;
  std::string error;
  if (!segment_moments(problem, z, 1.0, integrator, moments, error)) {
    throw NoConvergence("integrating the exact point for its moments failed: " + error);
  }
  // Nondimensional moments times EI_scale/L; energy integral of m^2/(2 EI) ds times EI_scale/L.
  const double moment_scale = point.EI_scale / point.length_scale;
  const double N = std::hypot(point.Nx, point.Ny);
  for (std::size_t j = 0; j < moments.size(); ++j) {
    if (!moments[j].flexible) continue;
    add_segment(design,
                part,
                j,
                moments[j].strain_energy * moment_scale,
                moments[j].max_abs_moment * moment_scale,
                N,
                moments[j].theta_end - moments[j].theta_start,
                st);
  }
}

}  // namespace

ExactSegmentState exact_segment_state(const MechanismDesign& design,
                                      const ExactPoint& point,
                                      const ShootingSolver::Options& options) {
  if (!point.converged()) throw InvalidInput("exact_segment_state needs a converged point");
  const PhysicalChain pc = physical_chain(design);
  ExactSegmentState st;
  // The moments come from the step observer of an explicit Runge-Kutta backend.
  ShootingSolver::Options o = options;
  if (o.backend != ElasticaIntegrator::Backend::kDormandPrince) {
    o.backend = ElasticaIntegrator::Backend::kRk8pd;
  }
  for (const ChainPart& part : chain_parts(point, pc))
    add_chain_moments(design, part, point, o, st);
  return st;
}

}  // namespace flexure::mechanism
