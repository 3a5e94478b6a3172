#pragma once
// The model ladder's error-and-time map (`flexure models map`, docs/models.md; HDF5 layout in
// docs/hdf5-schema.md "flexure models map"): Howell's uniform cantilever solved over a grid of
// loads by every model of the ladder, each answer compared with the exact solution.
//
// The grid: the load ratio n, the transverse load alpha2 = P l^2/EI and, for a free end, the end
// moment mu = M l/EI; for a guided end the prescribed tip angle instead of mu (the tip moment is
// then the guide's reaction). The reference is the exact elastica: the elliptic solver for a free
// end, the shooting method (rtol 1e-12) for a guided end. A model's error at a point:
//   position_error = |(a, b) - (a, b)_exact| (per length l), angle_error = |theta0 - theta0_exact|,
//   relative_error = position_error / |(a - 1, b)_exact| (the tip displacement; the measure of
//   `--tol`, beam_problem.h).
// Its time per solve: the library call solve_beam (beam_problem.h) without a shape, repeated at
// each point until `min_seconds` have passed, the mean taken (so that a closed form taking
// microseconds is timed as well as a shooting solve taking milliseconds). That includes the few
// microseconds every method spends filling a BeamSolution: the floor of the chart.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure::studies {

// What a model's answer at a point is (the `status` dataset of each model group).
enum class ModelPointStatus : int {
  kConverged = 0,       // errors and time recorded
  kNotConverged = 1,    // the model's solve did not converge
  kNotRepresented = 2,  // the model cannot represent this load (e.g. the 1R model with mu != 0)
  kNoReference = 3,     // the exact solution did not converge here: no error recorded
};

struct ModelMapSpec {
  EndCondition boundary = EndCondition::kFree;  // kFree or kGuided
  std::vector<double> n = {0.0};
  std::vector<double> alpha2;
  std::vector<double> mu = {0.0};         // free end
  std::vector<double> tip_angle = {0.0};  // guided end, rad
  // The models, named by their --method name; default: every model that solves this end
  // (linear, prbm, prbm3r, bcm, cbcm, chain, shooting; the reference is not repeated).
  std::vector<BeamMethod> models;
  int cbcm_elements = 6;
  Prbm3rConstantSet prbm3r_constants = Prbm3rConstantSet::kSu;
  int chain_elements = 100;
  double min_seconds = 2e-4;  // timing per point and model

  // The models to run: `models`, or the default for the end.
  std::vector<BeamMethod> model_list() const;
  // The reference method: elliptic (free), shooting (guided).
  BeamMethod reference() const;
  // The third axis: mu (free) or tip_angle (guided).
  const std::vector<double>& third_axis() const;
  const char* third_axis_name() const;
  std::size_t point_count() const;
  // Throws InvalidInput naming the field: the end, empty or non-finite axes, a mu axis on a
  // guided end (or a tip angle on a free one), a model listed twice or the reference itself, the
  // counts, min_seconds.
  void validate() const;
};

struct ModelMapColumns {
  std::vector<double> a_over_l, b_over_l, theta0;
  std::vector<double> position_error, angle_error, relative_error;
  std::vector<double> seconds;
  std::vector<int> status;
  void resize(std::size_t count);
};

struct ModelMapModel {
  BeamMethod method = BeamMethod::kLinear;
  std::string settings;  // e.g. "elements 6", "constants su"; empty for none
  ModelMapColumns values;
  // Summary over the converged points: count, largest and median position error, median time.
  long converged = 0;
  double max_position_error = 0.0;
  double median_position_error = 0.0;
  double median_seconds = 0.0;
};

struct ModelMap {
  ModelMapSpec spec;
  ModelMapColumns reference;  // errors 0 where converged; seconds its time
  // Folds the exact load path passes before each load (proportional loading from zero): where
  // there are some, the beam snaps under load control and a model that follows the path stops
  // there (status 1) or may answer on another branch.
  std::vector<int> reference_limit_points;
  std::vector<ModelMapModel> models;
};

// Solves the grid (row-major: n slowest, the third axis fastest). `progress(done, total)` after
// each point. Throws InvalidInput for what ModelMapSpec::validate refuses.
ModelMap compute_model_map(const ModelMapSpec& spec,
                           const std::function<void(std::size_t, std::size_t)>& progress = {});

// Writes the map to `path` (atomic; provenance on the root; docs/hdf5-schema.md). Throws
// InvalidInput for an unwritable path.
void write_model_map(const ModelMap& map, const std::string& path);

}  // namespace flexure::studies
