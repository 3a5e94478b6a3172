#pragma once
// A beam sweep over one or two of Howell's parameters (`flexure sweep beam`): alpha2, the load
// ratio n, the end moment mu, or an inverse target theta0 or b/l, each either fixed or an equally
// spaced axis START:STOP:COUNT. Two axes make a grid, stored row-major (the second axis varies
// fastest), as datasets shaped [count1, count2] (docs/hdf5-schema.md "flexure sweep beam").
#include <optional>
#include <string>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/physical_beam.h"

namespace flexure {

// Howell's parameters, and the tip loads of a physical beam in SI (kFx, kFy: N; kM: N m), which
// sweep a BeamSweepGrid::physical beam (`sweep beam --length ... --Fy 0N:5N:51`).
enum class SweepParameter { kAlpha2, kLoadRatioN, kMu, kTheta0, kBOverL, kFx, kFy, kM };

// The dataset name ("alpha2", "load_ratio_n", "mu", "theta0", "b_over_l", "Fx", "Fy", "M") and
// the command-line flag ("--alpha2", "--n", "--mu", "--theta0", "--b-over-l", "--Fx", "--Fy",
// "--M").
const char* dataset_name(SweepParameter p);
const char* flag_name(SweepParameter p);
const char* units_of(SweepParameter p);  // "1", "rad", "N" or "N m"
bool is_physical(SweepParameter p);      // kFx, kFy, kM

struct SweepAxis {
  SweepParameter parameter = SweepParameter::kAlpha2;
  double start = 0.0;
  double stop = 0.0;
  long count = 1;
  double at(long i) const;  // exact at both ends
};

struct BeamSweepGrid {
  // Fixed values and the methods' settings; `base.given` is the load or the inverse target swept
  // or fixed (kAlpha2, kTheta0 or kBOverL), `base.value` its fixed value when it is not an axis.
  BeamProblem base;
  std::vector<SweepAxis> axes;  // one or two
  // A physical sweep: the beam in SI units whose tip loads Fx, Fy, M the axes kFx, kFy, kM set
  // (the others keep the beam's); each point is that beam's problem (PhysicalCantilever::
  // to_problem, with base's settings), so its results are per unit length and in Howell's
  // nondimensional loads (length_m, EI_Nm2 scale them). Only physical axes then.
  std::optional<PhysicalCantilever> physical;
  // A chain (`sweep beam --chain FILE`): the tip load of this chain is what the axes kFx, kFy,
  // kM set (in the chain's units: N and N m where chain_in_si), each point that chain with its
  // own end condition. Only physical axes then; results per unit total length.
  std::optional<SegmentChain> chain;
  bool chain_in_si = false;

  // Throws InvalidInput naming the flag: one or two axes, not the same parameter twice, an axis of
  // theta0 or b/l only for that inverse problem (the given quantity is one of alpha2, theta0,
  // b/l), b/l within [-1, 1], at most `max_points` points in all.
  void validate(long max_points) const;
  long size() const;                // points in all
  std::vector<long> shape() const;  // the axes' counts
  // The problem at point `index` (row-major over the axes).
  BeamProblem at(long index) const;
  // The value of each axis at point `index`.
  std::vector<double> coordinates(long index) const;
  // "alpha2" or "alpha2,load_ratio_n": the axes in order.
  std::string axis_names() const;
  // Whether some point is a problem the elliptic solution does not take (a held end; a physical
  // beam with distributed loads, a curvature, a taper, or an axial tip force with Fy = 0): what
  // `sweep beam --method auto` then solves by the shooting method.
  bool needs_shooting() const;
};

}  // namespace flexure
