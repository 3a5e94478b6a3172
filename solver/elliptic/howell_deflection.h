#pragma once
// The tip deflection b/l on the mu = 0 branch (howell_branch.h) as an explicit function of the tip
// angle, with its slope, and the inverse: the smallest load whose tip reaches a given b/l.
//
// On the branch the load rises monotonically with the tip angle theta0 in (0, psi) (Howell eq.
// 2.90), so the smallest load reaching b/l is the smallest theta0 with b(theta0) = b/l. b(theta0)
// rises from 0 and, for compressive load ratios, peaks and falls back towards sin(psi) as the tip
// curls past the top (one interior maximum at most: checked on 20000 tip angles for every n in
// [-30, 30] in steps of 0.05). Newton's method in theta0 with the exact slope, kept inside a
// bracket, finds the first crossing in a handful of evaluations, each costing one Carlson
// duplication (about 0.2 us) instead of a forward solve.
namespace flexure::elliptic {

struct BranchDeflection {
  double b = 0.0;      // b/l in the normalised frame (force angle psi in (0, pi)): positive
  double slope = 0.0;  // d(b/l)/d theta0
  double force = 0.0;  // F l^2/EI at this tip angle (Howell eq. 2.90)
  // The slope loses about -log10(k'^2) digits to cancellation near the separatrix; it is trusted
  // (8 digits or more) for k'^2 > 1e-8.
  bool slope_reliable = false;
};
// psi in (0, pi), theta0 in (0, psi).
BranchDeflection branch_deflection(double psi, double theta0);

struct DeflectionInverse {
  bool found = false;  // false: the search could not settle it (see below); nothing is claimed
  double theta0 = 0.0;
  int evaluations = 0;
};
// The smallest theta0 in (0, psi) with b(theta0) = target in (0, 1), to round-off, among loads
// F <= max_force. Not found (the caller then scans the load) when the tip angle reached is past
// the peak of b while b is still below the target (the target lies above the peak or needs the
// peak located), when the load would exceed max_force, near the separatrix where the slope is not
// trusted, or when the iteration does not settle.
DeflectionInverse first_tip_angle_for_deflection(double psi, double target, double max_force);

}  // namespace flexure::elliptic
