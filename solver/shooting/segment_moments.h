#pragma once
// Bending-moment statistics of every flexible segment of a solved shooting problem, from one
// integration of its unknowns (no Newton iteration, no sampled shape): the largest |m|, the strain
// energy integral of m^2/(2 EI) ds and the tangent angle at both ends.
//
// On every accepted step [s0, s1] of the explicit integrator the moment is interpolated by the
// quintic Hermite polynomial through m, m' and m'' at both ends (m' = N_x sin theta -
// N_y cos theta and m'' = (N_x cos theta + N_y sin theta) theta' follow from the state; Howell
// eqs. 2.67-2.69), whose error is O(h^6) (Burden & Faires, Numerical Analysis, §3.4, Hermite
// interpolation); its extrema inside the step (roots of the quartic derivative) give max |m|, and
// six-point Gauss-Legendre quadrature of its square over the step (exact for degree 11) gives the
// energy. Both are then as accurate as the integrated state itself, where a sampled shape (801
// points) leaves O(ds^2) in both.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/shooting_problem.h"

namespace flexure {

struct SegmentMoments {
  bool flexible = false;        // false for a rigid segment (all fields zero)
  double max_abs_moment = 0.0;  // max over the segment of |m(s)|
  double strain_energy = 0.0;   // integral over the segment of m^2 / (2 EI(s)) ds
  double theta_start = 0.0;     // tangent angle at the segment's near end
  double theta_end = 0.0;       // ... and at its far end
};

// One entry per segment of problem.chain(). `z` must hold all unknowns of `problem` (root loads
// and any multiple-shooting cut states), e.g. a converged ShootingResult::unknowns. The
// integrator must use an explicit Runge-Kutta backend (kRk8pd or kDormandPrince). Returns false
// with `error` when the integration fails.
bool segment_moments(const ShootingProblem& problem,
                     const Eigen::VectorXd& z,
                     double lambda,
                     ElasticaIntegrator& integrator,
                     std::vector<SegmentMoments>& out,
                     std::string& error);

}  // namespace flexure
