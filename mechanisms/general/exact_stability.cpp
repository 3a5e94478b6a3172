#include "flexure/mechanisms/general/exact_stability.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flexure::mechanism::general {

using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXd exact_null_space(const MatrixXd& A, int cols) {
  if (A.rows() == 0) {
    return MatrixXd::Identity(cols, cols);
  }
  Eigen::JacobiSVD<MatrixXd> svd(A, Eigen::ComputeFullV);
  const VectorXd& sv = svd.singularValues();
  const double cut = 1e-9 * std::max(1.0, sv.size() > 0 ? sv[0] : 0.0);
  int rank = 0;
  for (int i = 0; i < sv.size(); ++i) {
    rank += sv[i] > cut ? 1 : 0;
  }
  return svd.matrixV().rightCols(cols - rank);
}

CondensedVerdict condensed_verdict(const MatrixXd& compliance, const MatrixXd& reference) {
  CondensedVerdict v;
  if (compliance.rows() == 0) {
    return v;
  }
  if (!compliance.allFinite()) {
    v.margin = 0.0;
    return v;
  }
  const MatrixXd C = 0.5 * (compliance + compliance.transpose());
  const MatrixXd R = 0.5 * (reference + reference.transpose());
  Eigen::SelfAdjointEigenSolver<MatrixXd> r(R);
  const VectorXd d = r.eigenvalues();
  const double stiffest = std::max(d.maxCoeff(), 0.0);
  VectorXd nu;
  if (stiffest > 0.0 && d.minCoeff() > 1e-9 * stiffest) {
    // nu = eigenvalues of L^T C L with L = V D^(1/2) (R = L L^T).
    const MatrixXd L = r.eigenvectors() * d.cwiseSqrt().asDiagonal();
    nu = Eigen::SelfAdjointEigenSolver<MatrixXd>(L.transpose() * C * L, Eigen::EigenvaluesOnly)
             .eigenvalues();
  } else {
    // A free direction that strains no flexure or spring to first order (a toggle position):
    // measured against the stiffest direction instead, as the PRBM's verdict does.
    nu = Eigen::SelfAdjointEigenSolver<MatrixXd>(C, Eigen::EigenvaluesOnly).eigenvalues() *
         (stiffest > 0.0 ? stiffest : 1.0);
  }
  const double eps = 1e-9 * std::max(1.0, nu.cwiseAbs().maxCoeff());
  double closest_negative = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < nu.size(); ++i) {
    if (nu[i] < -eps) {
      ++v.index;
      closest_negative = std::max(closest_negative, nu[i]);
    }
  }
  if (v.index > 0) {
    v.margin = 1.0 / closest_negative;
  } else if (nu.maxCoeff() > eps) {
    v.margin = std::min(1.0, 1.0 / nu.maxCoeff());
  }
  return v;
}

}  // namespace flexure::mechanism::general
