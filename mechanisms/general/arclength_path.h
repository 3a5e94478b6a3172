#pragma once
// Pseudo-arclength continuation of a curve F(y) = 0 (F: size - 1 equations in `size` unknowns),
// shared by the general mechanism's PRBM (general_prbm.cpp: y = (q, mu, lambda, s)) and exact
// model (general_exact.cpp: y = (bodies, multipliers, flexure loads, lambda, s)). One component,
// the controlled one (the input load under force control, the input coordinate under displacement
// control), is followed to a target through the limit points of the curve: the tangent from the
// bordered Jacobian [dF/dy; t^T], a predictor along it, a corrector on the hyperplane normal to it,
// and a step that halves on failure or on a sharp turn (the step may have jumped to another branch)
// and grows by 1.5 after an easy correction (docs/mechanisms.md "Continuation"). Limit points of
// the controlled component are located by bisection of the arclength on the sign of the tangent's
// component; grid values crossed are solved for by Newton with the component held.
#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {

struct ArclengthCurve {
  int size = 0;  // unknowns; the residual has size - 1 components
  // F(y); false where it cannot be evaluated.
  std::function<bool(const Eigen::VectorXd& y, Eigen::VectorXd& F)> residual;
  // dF/dy, (size - 1) x size; false where it cannot be evaluated.
  std::function<bool(const Eigen::VectorXd& y, Eigen::MatrixXd& J)> jacobian;
  // The arclength's metric: |dy|^2 = sum weight_i dy_i^2 (ones: Euclidean). Unknowns on other
  // scales than the ones followed get weight 0.
  Eigen::VectorXd weight;
};

struct ArclengthSettings {
  double tolerance = 1e-10;        // on |F| (and the arclength equation), infinity norm
  int max_newton_iterations = 30;  // per Newton solve
  double max_step = 0.05;          // the largest arclength step
  int max_steps = 10000;           // accepted steps over all follows of one path
};

class ArclengthPath {
 public:
  ArclengthPath(ArclengthCurve curve, ArclengthSettings settings);

  // Newton on F = 0 with y[fixed] held; true when it converged (y updated in place).
  bool newton_fixed(Eigen::VectorXd& y, int fixed);
  // Unit tangent (weighted norm) at y, oriented along `orient` (weighted).
  bool tangent(const Eigen::VectorXd& y, const Eigen::VectorXd& orient, Eigen::VectorXd& t);
  // Corrector from the predictor y on the hyperplane t . W (y - base) = h: its iterations, or -1.
  int corrector(Eigen::VectorXd& y,
                const Eigen::VectorXd& base,
                const Eigen::VectorXd& t,
                double h);

  struct Follow {
    int controlled = 0;  // the component followed to the target
    // Recording: the values of the controlled component at which `record` is called with the
    // point solved there (in the order of travel), and every accepted step kept in dense().
    const std::vector<double>* grid = nullptr;
    std::function<void(const Eigen::VectorXd&)> record;
    std::function<void(const Eigen::VectorXd&)> limit;  // at each located limit point
    std::function<bool()> give_up;  // checked after each recorded step: true ends in kLimitPoint
  };
  // Follows the curve from y until the controlled component reaches `target` (y is then the
  // point solved there: kConverged), the steps run out (kLimitPoint), or a step cannot be made
  // (kNoConvergence).
  Termination follow(Eigen::VectorXd& y, double target, const Follow& how);

  // Points of the dense path where component `index` changes sign, each refined by Newton with it
  // held at zero (the unloaded equilibria when `index` is the input load). A bracket whose Newton
  // fails is returned in `failed` (its first point).
  std::vector<Eigen::VectorXd> zeros_along(int index, std::vector<Eigen::VectorXd>* failed);

  const std::vector<Eigen::VectorXd>& dense() const { return dense_; }
  int steps() const { return steps_; }
  int iterations() const { return iterations_; }    // Jacobians factorised
  double worst_residual() const { return worst_; }  // largest |F| at a converged Newton solve

 private:
  ArclengthCurve c_;
  ArclengthSettings o_;
  std::vector<Eigen::VectorXd> dense_;
  int steps_ = 0;
  int iterations_ = 0;
  double worst_ = 0.0;
};

}  // namespace flexure::mechanism::general
