#pragma once
// The discrete second variation of a segment chain's potential energy and its constrained
// eigenvalues: the linear algebra of the chain's stability verdict (docs/stability.md, method 1;
// the assembly from a shape is in equilibrium_stability.cpp).
//
// Degrees of freedom: eta = delta theta at the element nodes that can move (eta(0) = 0 at the
// clamp; eta is constant along a rigid link; eta(L) = 0 is removed when the tip angle is
// prescribed). On them
//     Q[eta] = eta^T (B + W) eta,   B: int EI eta'^2 ds (tridiagonal, positive definite),
//                                  W: int (N . t) eta^2 ds (diagonal, lumped),
// and the admissible variations satisfy C eta = 0 (linearised prescribed tip coordinates). The
// constrained eigenvalues lambda of Q eta = lambda B eta (C eta = 0) are 1 + nu with nu those of
// W relative to B: they accumulate at 1 (W is compact relative to B), an eigenvalue below 1 exists
// exactly where some admissible direction is compressed, and with sigma = 1 / (1 - lambda)
//     Q - lambda B = (1 - lambda) (B + sigma W),
// so the number of constrained eigenvalues below lambda < 1 is the number of negative eigenvalues
// of A(sigma) = B + sigma W on ker C. That is counted without forming a basis of ker C by the
// bordered-matrix inertia (Haynsworth 1968; Maddocks 1987, "Stability and folds", Arch. Rational
// Mech. Anal. 99, Theorem 1): with A nonsingular and C of full row rank m,
//     In [A C^T; C 0] = In(A) + In(-S),  S = C A^{-1} C^T,   and   In [A C^T; C 0] =
//     In(Z^T A Z) + (m, m, 0),  hence  neg(Z^T A Z) = neg(A) - neg(S) - zero(S).
// neg(A) is the number of negative pivots of A = L D L^T (Sylvester's law of inertia); S is m x m
// (m <= 2) from m tridiagonal solves: O(n) per count.
//
// The eigenvalue itself: the count brackets it (bisection in lambda) and Newton's method on
// det [A C^T; C 0], a polynomial in sigma with only real roots (the constrained eigenvalues), whose
// logarithmic derivative is tr(A^{-1} W) + tr(S^{-1} dS/dsigma), dS/dsigma = -X^T W X,
// X = A^{-1} C^T, both O(n), converges quadratically once the bracket holds that one root alone.
#include <array>
#include <vector>

namespace flexure {

struct DiscreteSecondVariation {
  std::vector<double> bending_diag;  // B(i, i)
  std::vector<double> bending_off;   // B(i, i + 1), size n - 1
  std::vector<double> axial;         // W(i, i)
  // Rows of C (each of size n, at most 2), linearly independent (dependent or vanishing rows
  // removed).
  std::vector<std::vector<double>> constraints;
  // The constraints' compliance D (symmetric, over the rows of `constraints`: D00, D01, D11),
  // zero for an inextensible chain. An extensible or shear-flexible chain (docs/extensible.md,
  // "Stability") does not hold its tip coordinates rigidly against a bending direction: its
  // second variation condensed on eta is Q[eta] + (C eta)^T D^{-1} (C eta) (the stretch and
  // shear that keep the tip in place cost that energy), which the bordered inertia counts with
  // S = C A^{-1} C^T + D / sigma (the bordered matrix [A C^T; C -D/sigma]; D = 0 is the rigid
  // constraint C eta = 0). D need not be regular; a direction with D = 0 must have a nonvanishing
  // row.
  std::array<double, 3> compliance{0.0, 0.0, 0.0};
  // Gamma >= 0 with lambda_1 >= 1 - Gamma for every constrained eigenvalue (0: no compressed
  // direction, no eigenvalue below 1). From eta_i^2 <= G_i B[eta], G_i the sum of 1/B_e over the
  // elements between the clamp and node i (Cauchy-Schwarz): Gamma = sum_i max(0, -W_ii) G_i.
  double compression_bound = 0.0;

  int size() const { return static_cast<int>(bending_diag.size()); }
};

// Inertia at lambda < 1 (sigma = 1 / (1 - lambda)).
struct PencilInertia {
  int count = 0;       // constrained eigenvalues below lambda: neg(A) - neg(S) - zero(S)
  int negative_A = 0;  // negative eigenvalues of the unconstrained A(sigma)
  int negative_S = 0;  // of S = C A^{-1} C^T
  int zero_S = 0;
  // d/dsigma log |det [A C^T; C 0]| (Newton's step is -1 / this, in sigma).
  double log_det_slope = 0.0;
};
// Where A(sigma) is singular to rounding S is large but its sign, and the count, stay right (the
// dense projection in tests/solver/stability_discretisation_test.cpp checks it there).
PencilInertia constrained_inertia(const DiscreteSecondVariation& q, double lambda);
inline int constrained_count(const DiscreteSecondVariation& q, double lambda) {
  return constrained_inertia(q, lambda).count;
}

struct PencilEigenvalue {
  bool exists = false;  // false: fewer than k constrained eigenvalues below 1 (value = 1)
  double value = 1.0;
  int evaluations = 0;  // inertia evaluations spent
};
// The k-th (k >= 1) constrained eigenvalue below 1, to `tolerance` times max(1, |lambda|) or the
// rounding noise of the inertia there, 1e-17 n^2 (1 - lambda), whichever is larger; `guess`
// (optional, < 1) is where to start looking (e.g. the same eigenvalue on a coarser grid) and
// `guess_radius` (> 0) how far off it may be (default 1e-3 max(1, |guess|)); a wrong guess costs
// evaluations, never the answer.
PencilEigenvalue constrained_eigenvalue(const DiscreteSecondVariation& q,
                                        int k,
                                        double tolerance,
                                        const double* guess = nullptr,
                                        double guess_radius = 0.0);

// The k-th constrained eigenvalue over a ladder of grids of one problem (`levels[0]` the finest,
// each next one with every 2nd sample of the one before), Romberg-extrapolated: the discrete
// eigenvalues are lambda + c1 h^2 + c2 h^4 + O(h^6) (uniform elements, symmetric quadrature), so
// R1 = (4 lambda_{h/2} - lambda_h)/3 = lambda + O(h^4) and (16 R1_{h/2} - R1_h)/15 = lambda +
// O(h^6). Solved from the coarsest grid to the finest, each starting from the previous grids'
// extrapolation (a few Newton steps instead of a search). Returns at most 1 (1 when the finest
// grid has no k-th eigenvalue below 1). `error` (optional): the difference between the best and
// the second-best extrapolation (HUGE_VAL on one grid, 0 without an eigenvalue); `fine_value`
// (optional): the finest grid's own eigenvalue.
double extrapolated_eigenvalue(const std::vector<const DiscreteSecondVariation*>& levels,
                               int k,
                               double tolerance,
                               double* error = nullptr,
                               double* fine_value = nullptr);

// Solves the bordered system [a B + b W, C^T; C, 0] [x; mu] = [rhs; 0] by a sparse LU with partial
// pivoting, so a B + b W may be indefinite or singular as long as the bordered matrix is not (it is
// nonsingular exactly where a B + b W is nonsingular on ker C and C has full row rank). `rhs` and
// `x` have q.size() entries (mu is dropped). Returns false when the matrix is singular.
bool solve_bordered(const DiscreteSecondVariation& q,
                    double bending_factor,
                    double axial_factor,
                    const std::vector<double>& rhs,
                    std::vector<double>& x);

// The eigenvector of the constrained pencil for the eigenvalue `lambda` < 1 (a value that
// constrained_eigenvalue returned): C eta = 0, eta^T B eta = 1, signed so that its component of
// largest magnitude is positive. By inverse iteration on the bordered matrix at sigma = 1 / (1 -
// lambda) moved off the eigenvalue by 1e-9 of it (about 1e-9 relative to the gap to the next
// eigenvalue per iteration: a few iterations). Used to follow an unstable direction off an
// equilibrium (solver/shooting/stable_equilibrium.h). Throws NoConvergence when the iteration does
// not settle (a multiple eigenvalue, or lambda not an eigenvalue), InvalidInput for lambda >= 1.
std::vector<double> constrained_eigenvector(const DiscreteSecondVariation& q, double lambda);

// Independent combinations of a grid's linearised tip-coordinate rows (at most 2 raw rows:
// int sin(theta) eta ds if x is held, int cos(theta) eta ds if y is), as coefficient pairs over
// the raw rows: the eigenvectors of their Gram matrix in the lumped L2 metric (weight = the lumped
// int eta^2 ds at each dof, so |row|^2 ~ int g^2 ds over the movable part) scaled to unit norm,
// keeping those whose eigenvalue exceeds 1e-20 of the length `total`, i.e. whose rms over the
// chain exceeds 1e-10. A vanishing row (x held on a straight chain along x: int sin(theta) eta = 0
// for every eta) constrains nothing at first order; its reaction still acts through N. Used by the
// chain's and the mechanism's assembly (equilibrium_stability.cpp, mechanism_second_variation.cpp).
std::vector<std::array<double, 2>> independent_row_combinations(
    const std::vector<std::vector<double>>& raw_rows,
    const std::vector<double>& weight,
    double total);

// The constraint rows C of DiscreteSecondVariation: each combination applied to the raw rows.
std::vector<std::vector<double>> combine_rows(
    const std::vector<std::vector<double>>& raw_rows,
    const std::vector<std::array<double, 2>>& combinations);

}  // namespace flexure
