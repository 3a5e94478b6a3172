#include "flexure/solver/shooting/segment_moments.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "flexure/solver/shooting/elastica_piece.h"
#include "flexure/solver/shooting/moment_interpolant.h"

namespace flexure {

namespace {

// Largest |p| on the step: the ends and the interior extrema.
double max_abs(const MomentQuintic& p) {
  double best = std::max(std::abs(p(0.0)), std::abs(p(1.0)));
  for (double t : p.interior_extrema()) best = std::max(best, std::abs(p(t)));
  return best;
}

// Collects the statistics of the flexible segments from the accepted steps.
class MomentCollector : public StepObserver {
 public:
  MomentCollector(const SegmentChain& chain, std::vector<SegmentMoments>& out) : out_(out) {
    out_.assign(chain.segments.size(), SegmentMoments{});
    s_first_.assign(chain.segments.size(), std::numeric_limits<double>::infinity());
    s_last_.assign(chain.segments.size(), -std::numeric_limits<double>::infinity());
    for (const Segment& seg : chain.segments) {
      const auto* f = std::get_if<FlexibleSegment>(&seg);
      segments_.push_back(f);
    }
    for (std::size_t j = 0; j < segments_.size(); ++j) out_[j].flexible = segments_[j] != nullptr;
  }

  void accepted_step(const ElasticaPieceData& piece,
                     double s0,
                     const double* y0,
                     const double* f0,
                     double s1,
                     const double* y1,
                     const double* f1) override {
    const auto it = std::find(segments_.begin(), segments_.end(), piece.segment);
    if (it == segments_.end()) return;
    const std::size_t j = static_cast<std::size_t>(it - segments_.begin());
    SegmentMoments& m = out_[j];
    if (s0 < s_first_[j]) {
      s_first_[j] = s0;
      m.theta_start = y0[kElasticaTheta];
    }
    if (s1 > s_last_[j]) {
      s_last_[j] = s1;
      m.theta_end = y1[kElasticaTheta];
    }
    const double h = s1 - s0;
    const MomentQuintic c(piece, s0, y0, f0, s1, y1, f1);
    m.max_abs_moment = std::max(m.max_abs_moment, max_abs(c));
    // Six-point Gauss-Legendre on [0, 1] (Abramowitz & Stegun, Table 25.4).
    static constexpr std::array<double, 3> kNodes{
        0.2386191860831969, 0.6612093864662645, 0.9324695142031521};
    static constexpr std::array<double, 3> kWeights{
        0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
    double sum = 0.0;
    for (std::size_t q = 0; q < kNodes.size(); ++q) {
      for (double sign : {-1.0, 1.0}) {
        const double t = 0.5 * (1.0 + sign * kNodes[q]);
        const double p = c(t);
        sum += kWeights[q] * p * p * piece.inv_EI(s0 + t * h);
      }
    }
    // (h/2) sum is the integral of m^2/EI over the step; the energy is half of it.
    m.strain_energy += 0.25 * h * sum;
  }

 private:
  std::vector<SegmentMoments>& out_;
  std::vector<const FlexibleSegment*> segments_;
  std::vector<double> s_first_, s_last_;
};

}  // namespace

bool segment_moments(const ShootingProblem& problem,
                     const Eigen::VectorXd& z,
                     double lambda,
                     ElasticaIntegrator& integrator,
                     std::vector<SegmentMoments>& out,
                     std::string& error) {
  MomentCollector collector(problem.chain(), out);
  integrator.set_step_observer(&collector);
  struct Detach {
    ElasticaIntegrator& integrator;
    ~Detach() { integrator.set_step_observer(nullptr); }
  } detach{integrator};
  TipState tip;
  return problem.integrate_solution(z, lambda, integrator, tip, error);
}

}  // namespace flexure
