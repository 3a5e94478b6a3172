#include "flexure/solver/shooting/segment_moments.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "flexure/solver/shooting/elastica_piece.h"

namespace flexure {

namespace {

// p(t) = sum c[k] t^k on t in [0, 1].
double polynomial(const std::array<double, 6>& c, double t) {
  return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
}
double derivative(const std::array<double, 6>& c, double t) {
  return c[1] + t * (2.0 * c[2] + t * (3.0 * c[3] + t * (4.0 * c[4] + t * 5.0 * c[5])));
}

// Largest |p| on [0, 1]: the ends and the zeros of p' (a quartic), bracketed on eight sub-intervals
// and bisected to rounding.
double max_abs(const std::array<double, 6>& c) {
  double best = std::max(std::abs(c[0]), std::abs(polynomial(c, 1.0)));
  constexpr int kBrackets = 8;
  double a = 0.0, da = derivative(c, 0.0);
  for (int i = 1; i <= kBrackets; ++i) {
    const double b = static_cast<double>(i) / kBrackets;
    const double db = derivative(c, b);
    if ((da < 0.0) != (db < 0.0)) {
      double lo = a, hi = b, dlo = da;
      for (int k = 0; k < 60 && hi - lo > 1e-15; ++k) {
        const double mid = 0.5 * (lo + hi);
        const double dm = derivative(c, mid);
        if ((dm < 0.0) == (dlo < 0.0)) {
          lo = mid;
          dlo = dm;
        } else {
          hi = mid;
        }
      }
      best = std::max(best, std::abs(polynomial(c, 0.5 * (lo + hi))));
    }
    a = b;
    da = db;
  }
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
    // m'' = (N_x cos theta + N_y sin theta) theta' (differentiating m' = N_x sin - N_y cos).
    auto second = [&](const double* y, const double* f) {
      const double th = y[kElasticaTheta];
      return (piece.Nx * std::cos(th) + piece.Ny * std::sin(th)) * f[kElasticaTheta];
    };
    // Quintic Hermite interpolant in t = (s - s0)/h: p, p', p'' match m, h m', h^2 m'' at t = 0, 1.
    std::array<double, 6> c{};
    c[0] = y0[kElasticaM];
    c[1] = h * f0[kElasticaM];
    c[2] = 0.5 * h * h * second(y0, f0);
    const double r0 = y1[kElasticaM] - (c[0] + c[1] + c[2]);
    const double r1 = h * f1[kElasticaM] - (c[1] + 2.0 * c[2]);
    const double r2 = h * h * second(y1, f1) - 2.0 * c[2];
    c[3] = 10.0 * r0 - 4.0 * r1 + 0.5 * r2;
    c[4] = -15.0 * r0 + 7.0 * r1 - r2;
    c[5] = 6.0 * r0 - 3.0 * r1 + 0.5 * r2;
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
        const double p = polynomial(c, t);
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
