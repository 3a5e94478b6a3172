// The state of the flexible segments of a solved exact point (mechanism_exact.h): stresses, strain
// energy and rotations, either from one integration of the solution (exact_segment_state without
// a sample count: what `mechanism analyze` reports) or from its shape sampled at equally spaced arc
// lengths (the trapezoidal rule of exact_strain_energy, kept as an independent check).
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/errors.h"
#include "flexure/solver/shooting/segment_moments.h"

namespace flexure::mechanism {

namespace {

// Adds the stresses and strain energy of the flexible segments of one nondimensional chain, solved
// from `unknowns`, whose internal force (tip load) is (Nx, Ny) N and root moment m0 N m in the
// chain's own frame; `pivots[j]` = pivot of segment j (0 rigid).
void accumulate_chain(const MechanismDesign& design,
                      const SegmentChain& chain,
                      const std::vector<double>& unknowns,
                      const std::vector<int>& pivots,
                      double m0,
                      double Nx,
                      double Ny,
                      double L,
                      double EI_scale,
                      int shape_points,
                      ExactSegmentState& st) {
  ShootingSolver::Options o;
  o.shape_points = shape_points;
  const ShootingResult r = ShootingSolver(o).solve_from(chain, unknowns);
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
      U *= L / (2.0 * f->EI * EI_scale);
      st.strain_energy += U;
      const int pivot = j < pivots.size() ? pivots[j] : 0;
      if (pivot > 0) {
        const JointDesign& jd = design.joints[pivot - 1];
        const RectangularSection section = jd.section(design.E);
        const double sigma =
            m_max * 0.5 * jd.thickness / section.second_moment() + N / section.area();
        st.max_stress[pivot - 1] = std::max(st.max_stress[pivot - 1], sigma);
        st.pivot_strain_energy[pivot - 1] += U;
        st.pivot_rotation[pivot - 1] += end.theta - start.theta;
        st.has_pivot[pivot - 1] = true;
      }
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
  const auto accumulate = [&](const SegmentChain& chain,
                              const std::vector<double>& unknowns,
                              const std::vector<int>& pivots,
                              double m0) {
    accumulate_chain(design,
                     chain,
                     unknowns,
                     pivots,
                     m0,
                     point.Nx,
                     point.Ny,
                     point.length_scale,
                     point.EI_scale,
                     shape_points,
                     st);
  };
  accumulate(point.chain, point.unknowns, pc.flexible_pivot, point.m0);
  if (!point.coupler_chain.segments.empty()) {
    // The coupler chain's frame is the root frame turned by pi about the slider: its tip load
    // (the crank's push on the coupler, -N, turned by pi) is +N in that frame.
    accumulate(
        point.coupler_chain, point.coupler_unknowns, pc.coupler_flexible_pivot, point.coupler_m0);
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
                       const SegmentChain& chain,
                       const std::vector<double>& unknowns,
                       const std::vector<int>& pivots,
                       double Nx,
                       double Ny,
                       double L,
                       double EI_scale,
                       const ShootingSolver::Options& options,
                       ExactSegmentState& st) {
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
  const double moment_scale = EI_scale / L;
  const double N = std::hypot(Nx, Ny);
  for (std::size_t j = 0; j < moments.size(); ++j) {
    if (!moments[j].flexible) continue;
    const double U = moments[j].strain_energy * moment_scale;
    st.strain_energy += U;
    const int pivot = j < pivots.size() ? pivots[j] : 0;
    if (pivot == 0) continue;
    const JointDesign& jd = design.joints[pivot - 1];
    const RectangularSection section = jd.section(design.E);
    const double m_max = moments[j].max_abs_moment * moment_scale;
    const double sigma = m_max * 0.5 * jd.thickness / section.second_moment() + N / section.area();
    st.max_stress[pivot - 1] = std::max(st.max_stress[pivot - 1], sigma);
    st.pivot_strain_energy[pivot - 1] += U;
    st.pivot_rotation[pivot - 1] += moments[j].theta_end - moments[j].theta_start;
    st.has_pivot[pivot - 1] = true;
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
  add_chain_moments(design,
                    point.chain,
                    point.unknowns,
                    pc.flexible_pivot,
                    point.Nx,
                    point.Ny,
                    point.length_scale,
                    point.EI_scale,
                    o,
                    st);
  if (!point.coupler_chain.segments.empty()) {
    add_chain_moments(design,
                      point.coupler_chain,
                      point.coupler_unknowns,
                      pc.coupler_flexible_pivot,
                      point.Nx,
                      point.Ny,
                      point.length_scale,
                      point.EI_scale,
                      o,
                      st);
  }
  return st;
}

}  // namespace flexure::mechanism
