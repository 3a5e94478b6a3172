#pragma once
// Pseudo-arclength continuation of the shooting problem in the load factor lambda.
//
// Proportional loading (segment_chain.h): lambda = 0 is the stress-free chain, lambda = 1 the
// requested load. The path (z(s), lambda(s)) is parameterised by arc length in scaled variables
// (z / scale, lambda), so it passes limit points (snap-through, where lambda turns back) that
// stepping in lambda alone cannot. Predictor: the unit tangent (null vector of [dg/dz dg/dlambda]);
// corrector: Newton with the Keller constraint (newton.h). Steps grow after easy corrections and
// are halved after a failed one; below min_step the path stops and reports the lambda reached.
// Folds (the tangent's lambda-component changes sign) and simple bifurcation points (det dg/dz
// changes sign while lambda keeps its direction) are located to about 1e-10 in lambda, and the
// path can leave a bifurcation onto the other branch (docs/theory-shooting.md §5).
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/newton.h"
#include "flexure/solver/shooting/shooting_problem.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

// Sign of det dg/dz of an evaluation with its Jacobian (0 when it is exactly singular).
int jacobian_sign(const ShootingEvaluation& eval);

// Follows the path from lambda = 0 to lambda = 1 (or until it stops), starting from `start`
// (which must solve g(start, 0) = 0; default: problem.unloaded_unknowns()). Stops at once, with
// a message, when dg/dz is singular at the start (a bifurcation, e.g. shortening a straight
// inextensible chain). Folds and bifurcations passed are located (options) and recorded in
// special_points and, as points of their own (kLimitPoint, kBifurcation), in points.
LoadPath continue_load_path(const ShootingProblem& problem,
                            ElasticaIntegrator& integrator,
                            const ContinuationOptions& options,
                            const NewtonOptions& newton,
                            const Eigen::VectorXd* start = nullptr);

// True when dg/dz is rank deficient at (z, lambda) (relative threshold 1e-10).
bool singular_jacobian(const ShootingEvaluation& eval);

// det(dg/dz S) divided by the product of the row norms of dg/dz S: a scale-free signed measure of
// how singular dg/dz is, in [-1, 1] by Hadamard's inequality, with the sign of det(dg/dz).
double normalized_determinant(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& scale);

// The shape at arc lengths `s` (ascending) of the solution (z, lambda) and the bending moment at
// each of its points from the statics of the part between the clamp and the point (no derivative
// of the shape). Returns false with `error` when the integration fails.
bool shape_with_moments(const ShootingProblem& problem,
                        ElasticaIntegrator& integrator,
                        const Eigen::VectorXd& z,
                        double lambda,
                        const std::vector<double>& s,
                        std::vector<ShapePoint>& shape,
                        std::vector<double>& moment,
                        std::string& error);

}  // namespace flexure
