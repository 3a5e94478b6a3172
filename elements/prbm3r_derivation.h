#pragma once
// PR-3R constants derived by flexure itself (docs/models.md, "PR-3R constants"), the way
// prbm_derivation.h re-derives Howell's 1R constants: the link lengths gamma0..gamma3 and spring
// stiffnesses k1..k3 (elements/prbm3r.h) that minimise the PR-3R model's error against the exact
// elliptic elastica over a stated domain of tip loads.
//
// Objective: the root mean square over the domain's loads of
//   e^2 = (|tip - exact tip| / |exact tip displacement|)^2
//       + (|theta0 - exact theta0| / max(|exact theta0|, |exact tip displacement|))^2,
// the relative tip position error (the measure of --tol) and a relative tip angle error. A load
// the model cannot follow (no converged proportional loading) counts as e = 1.
// Parameters: gamma1, gamma2, gamma3 (gamma0 = 1 - their sum, every gamma >= 0.02) and ln k1..k3;
// Nelder-Mead from Su's general set, restarted from its best point until a restart gains less
// than 1e-6 (or `restarts` are spent).
#include <string>
#include <vector>

#include "flexure/elements/prbm3r.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct Prbm3rDerivationOptions {
  // The load domain: the free cantilever at every (n, alpha2, mu) of these axes whose exact
  // solution (proportional loading) has |theta0| <= max_tip_angle.
  std::vector<double> load_ratio_n{-2.0, -1.0, 0.0, 1.0};
  std::vector<double> alpha2{0.5, 1.0, 2.0, 3.0, 5.0, 7.5, 10.0};
  std::vector<double> mu{-2.0, -1.0, 0.0, 1.0, 2.0};
  double max_tip_angle = 2.0;  // rad
  int max_evaluations = 4000;  // objective evaluations per Nelder-Mead run
  int restarts = 4;
  // Throws InvalidInput naming the field: empty or non-finite axes, alpha2 <= 0 with mu = 0 only
  // (no load), max_tip_angle outside (0, pi], counts < 1.
  void validate() const;
  // The domain in words (for the data file and the report).
  std::string describe() const;
};

struct Prbm3rDerivation : SolveStatus {
  // iterations: objective evaluations; residual: the objective at the derived constants
  Prbm3rConstants constants;           // name "flexure"
  double objective = 0.0;              // RMS of e over the domain (above)
  double objective_su = 0.0;           // the same for Su's general set
  double max_position_error = 0.0;     // largest relative tip position error over the domain
  double max_position_error_su = 0.0;  // the same for Su's general set
  int loads = 0;                       // loads in the domain (exact solutions kept)
  std::string domain;                  // Prbm3rDerivationOptions::describe()
};

Prbm3rDerivation derive_prbm3r_constants(const Prbm3rDerivationOptions& options = {});

// The data file data/prbm3r_flexure_constants.csv for a derivation: a comment block with the
// provenance (`provenance`: tool version, commit, command), the objective and the domain, then one
// row "flexure" with the columns of data/su_prbm3r_constants.csv and the objective.
std::string prbm3r_constants_csv(const Prbm3rDerivation& derivation, const std::string& provenance);

}  // namespace flexure
