#pragma once
// Anderson acceleration, type II (Walker & Ni 2011), of a fixed-point iteration x = G(x): the next
// iterate is G(x) - dG gamma, gamma the least-squares fit of the residual f = G(x) - x by the last
// `depth` residual differences dF (dG the matching differences of the images). Used by the chain
// algorithm's passes, free and with tip constraints (chain_fixed_point.cpp,
// chain_constrained.cpp; docs/theory-chain.md).
#include <Eigen/Dense>
#include <algorithm>

namespace flexure {

class AndersonMixing {
 public:
  // `size` unknowns, the last `depth` >= 0 differences kept (0: plain iteration, x+ = G(x)).
  AndersonMixing(Eigen::Index size, int depth)
      : depth_(std::max(0, depth)),
        dF_(size, std::max(1, depth_)),
        dG_(size, std::max(1, depth_)) {}

  // Forgets the history (the extrapolation lost its way, or an extrapolated state was refused).
  void restart() {
    stored_ = 0;
    head_ = 0;
    have_previous_ = false;
  }

  // The last image G(x) given to next(), a state the plain iteration reached; valid when
  // has_previous().
  bool has_previous() const { return have_previous_; }
  const Eigen::VectorXd& previous_image() const { return g_previous_; }

  // Records the image g = G(x) and its residual f = g - x, and returns the next iterate.
  Eigen::VectorXd next(const Eigen::VectorXd& g, const Eigen::VectorXd& f) {
    if (depth_ > 0 && have_previous_) {
      dF_.col(head_) = f - f_previous_;
      dG_.col(head_) = g - g_previous_;
      head_ = (head_ + 1) % depth_;
      stored_ = std::min(stored_ + 1, depth_);
    }
    f_previous_ = f;
    g_previous_ = g;
    have_previous_ = true;
    Eigen::VectorXd x = g;
    if (stored_ > 0) {
      // Normal equations of the fit (depth <= 50, so depth x depth is cheap); a relative Tikhonov
      // term keeps them solvable when the columns become nearly dependent close to convergence.
      Eigen::MatrixXd gram = dF_.leftCols(stored_).transpose() * dF_.leftCols(stored_);
      constexpr double kRidge = 1e-12;
      gram.diagonal().array() += kRidge * gram.diagonal().maxCoeff() + 1e-300;
      const Eigen::VectorXd gamma = gram.ldlt().solve(dF_.leftCols(stored_).transpose() * f);
      if (gamma.allFinite()) x.noalias() -= dG_.leftCols(stored_) * gamma;
    }
    return x;
  }

 private:
  int depth_;
  Eigen::MatrixXd dF_, dG_;
  Eigen::VectorXd f_previous_, g_previous_;
  int stored_ = 0;  // columns in use
  int head_ = 0;    // next column to overwrite
  bool have_previous_ = false;
};

}  // namespace flexure
