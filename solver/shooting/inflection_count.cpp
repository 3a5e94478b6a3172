#include "flexure/solver/shooting/inflection_count.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "flexure/solver/shooting/elastica_piece.h"
#include "flexure/solver/shooting/moment_interpolant.h"

namespace flexure {

namespace {

constexpr int kFallbackShapePoints = 401;

}  // namespace

// The curvature at the ends of every accepted step and at the moment's interior extrema, in s.
void CurvatureRecorder::accepted_step(const ElasticaPieceData& piece,
                                      double s0,
                                      const double* y0,
                                      const double* f0,
                                      double s1,
                                      const double* y1,
                                      const double* f1) {
  const MomentQuintic m(piece, s0, y0, f0, s1, y1, f1);
  const double kappa0 = piece.segment->kappa0;
  const double h = s1 - s0;
  current_.push_back(y0[kElasticaM] * piece.inv_EI(s0) + kappa0);
  // With a constant EI the extrema of m are those of the curvature m/EI + kappa0. With an EI
  // profile they are close to them, and the step ends still bound every sign change to the step.
  for (double t : m.interior_extrema()) {
    current_.push_back(m(t) * piece.inv_EI(s0 + t * h) + kappa0);
  }
  current_.push_back(y1[kElasticaM] * piece.inv_EI(s1) + kappa0);
}

int CurvatureRecorder::inflection_points() const {
  return sign_changes(accepted_, 1e-9 * largest_curvature());
}

double CurvatureRecorder::largest_curvature() const {
  double largest = 0.0;
  for (double v : accepted_) largest = std::max(largest, std::fabs(v));
  return largest;
}

int sign_changes(const std::vector<double>& values, double zero) {
  int changes = 0;
  int previous = 0;
  for (double v : values) {
    if (!(std::fabs(v) > zero)) continue;
    const int sign = v > 0.0 ? 1 : -1;
    if (previous != 0 && sign != previous) ++changes;
    previous = sign;
  }
  return changes;
}

bool count_inflections(const ShootingProblem& problem,
                       const Eigen::VectorXd& z,
                       double lambda,
                       ElasticaIntegrator& integrator,
                       InflectionCount& out,
                       std::string& error) {
  const auto backend = integrator.options().backend;
  if (backend != ElasticaIntegrator::Backend::kRk8pd &&
      backend != ElasticaIntegrator::Backend::kDormandPrince) {
    // No steps to show: the sign changes of theta's increments along a sampled shape.
    std::vector<double> s;
    const double total = problem.chain().total_length();
    for (int i = 0; i < kFallbackShapePoints; ++i)
      s.push_back(total * i / (kFallbackShapePoints - 1));
    std::vector<ShapePoint> shape;
    if (!problem.integrate_solution(z, lambda, integrator, out.tip, error, &s, &shape))
      return false;
    std::vector<double> increments;
    for (std::size_t i = 1; i < shape.size(); ++i)
      increments.push_back(shape[i].theta - shape[i - 1].theta);
    out.inflection_points = sign_changes(increments, 1e-12);
    return true;
  }
  CurvatureRecorder recorder;
  integrator.set_step_observer(&recorder);
  struct Detach {
    ElasticaIntegrator& integrator;
    ~Detach() { integrator.set_step_observer(nullptr); }
  } detach{integrator};
  recorder.begin_evaluation();
  if (!problem.integrate_solution(z, lambda, integrator, out.tip, error)) return false;
  recorder.accept_evaluation();
  out.inflection_points = recorder.inflection_points();
  out.largest_curvature = recorder.largest_curvature();
  return true;
}

}  // namespace flexure
