#pragma once
// Data model of a benchmark run (`flexure bench`): the standard problems, the methods that solve
// them and one table of results per (problem, method). The HDF5 layout is docs/hdf5-schema.md.
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/shooting/elastica_integrator.h"

namespace flexure::bench {

// One load of a problem in Howell's parameters: Fx = -n alpha2, Fy = alpha2, end moment mu
// (EndLoad::howell, nondimensional with l = 1, EI = 1).
struct LoadPoint {
  double load_ratio_n = 0.0;
  double alpha2 = 0.0;
  double mu = 0.0;
  double displacement = 0.0;  // cfm_stroke only: slider displacement Delta x, m
};

struct BenchProblem {
  std::string name;                             // HDF5 group name, e.g. "cantilever_force"
  std::string description;                      // one sentence, stored as an attribute
  EndCondition boundary = EndCondition::kFree;  // kFree (cantilever) or kGuided (fixed-guided)
  std::vector<LoadPoint> points;
  // Non-empty: a constant-force mechanism stroke of this built-in design (mechanisms/mechanism.h);
  // its points are slider displacements, not beam loads, and only prbm and exact apply.
  std::string mechanism;
  bool is_mechanism() const { return !mechanism.empty(); }
  // The elliptic solver solves Howell's free cantilever with dead loads only.
  bool elliptic_applies() const { return boundary == EndCondition::kFree && !is_mechanism(); }
};

// kMechanismExact: the exact (shooting-based) mechanism model, ExactMechanismSolver; mechanism
// problems only.
enum class MethodFamily { kElliptic, kShooting, kChain, kPrbm, kMechanismExact };
const char* to_string(MethodFamily family);

struct BenchMethod {
  std::string name;  // HDF5 group name, e.g. "shooting_cvodes_rtol1e-09", "chain_N050_inc05"
  MethodFamily family = MethodFamily::kElliptic;
  ElasticaIntegrator::Backend backend = ElasticaIntegrator::Backend::kCvodes;  // shooting only
  double rtol = 1e-12;  // shooting only: integrator relative tolerance
  int elements = 0;     // chain only: N
  int increments = 0;   // chain only: largest load step 1/increments
};

// Status codes of one solve (dataset `status`).
inline constexpr int kStatusConverged = 0;     // converged, error measured
inline constexpr int kStatusNotConverged = 1;  // the solver returned converged == false
inline constexpr int kStatusError = 2;         // the solver threw (e.g. no PRBM root, bad input)
inline constexpr int kStatusNoReference = 3;   // converged, but the reference failed at this load

// The results of one method on one problem (one HDF5 group). Arrays have one entry per load point.
struct MethodRun {
  std::string problem;
  std::string method;      // BenchMethod::name, or "reference"
  std::string family;      // to_string(MethodFamily)
  std::string backend;     // shooting: "cvodes" | "dormand-prince"; otherwise ""
  double tolerance = 0.0;  // the method's convergence tolerance (rtol for shooting)
  int elements = 0;        // chain
  int increments = 0;      // chain
  std::vector<double> load_ratio_n, alpha2, mu;    // inputs
  std::vector<double> a_over_l, b_over_l, theta0;  // outputs (NaN when status != 0 and != 3)
  std::vector<double> error_position;              // |tip - reference tip| / l (NaN without both)
  std::vector<double> error_relative;              // error_position / |reference tip displacement|
  std::vector<double> error_theta0;                // |theta0 - reference theta0| [rad]
  std::vector<double> seconds;                     // median wall time of one solve over `repeats`
  std::vector<int> repeats;                        // solves timed
  std::vector<int> status;                         // kStatus*
  std::vector<int> iterations;                     // the solver's own iteration count
  std::vector<int> inside_validity;   // PRBM: 1 inside Theta_max, 0 outside; -1 other methods
  std::vector<int> reference_source;  // reference group only: 0 elliptic, 1 shooting rtol 1e-12,
                                      // 2 exact mechanism model (cfm_stroke)
  // cfm_stroke only (empty otherwise); there error_relative = error_force and the beam datasets
  // (inputs, a_over_l, b_over_l, theta0, error_position, error_theta0) are NaN.
  std::vector<double> displacement;  // slider displacement Delta x, m
  std::vector<double> force;         // slider input force, N (NaN when status != 0 and != 3)
  std::vector<double> error_force;   // |force - reference force| / |reference force|
  std::vector<std::string> message;  // empty when converged, else why not

  std::size_t size() const { return alpha2.size(); }
  std::string key() const { return problem + "/" + method; }
};

}  // namespace flexure::bench
