#pragma once
// A load sweep of the end-loaded cantilever and its HDF5 layout (`flexure sweep beam`).
//
// It lives in the library, not in cli/, so that benchmarks/perf/sweep_bench.cpp measures exactly
// what the tool does: solve every point (optionally on a few threads), then write each column with
// a single HDF5 call.
//
// File layout (one entry per point, in the order of the requested range; each dataset with its
// `units` and `description`; docs/hdf5-schema.md "flexure sweep beam"). A sweep over two
// parameters stores every dataset below shaped [count1, count2] and the axes in /axes:
//   /alpha2           float64  P l^2/EI (Howell eq. 2.83)
//   /a_over_l         float64  a/l, NaN where status != 0
//   /b_over_l         float64  b/l, NaN where status != 0
//   /theta0           float64  tip angle in rad, NaN where status != 0
//   /status           int32    0 converged, 1 no converged solution at this load
//   /within_validity  int32    PRBM validity per load (BeamSweepPoint::within_validity)
//   /stability        int32    the verdict (docs/stability.md): 0 stable, 1 unstable, 2
//                              critical, 3 not_conservative, 4 not_checked (also where status != 0)
//   /stability_index  int32    negative directions of the energy; -1 where not judged (3, 4)
//   /stability_margin float64  lowest eigenvalue / bending stiffness; NaN where not judged
// Root attributes: method, load_ratio_n, mu, tolerance, count, converged_count and the
// provenance of io/platform/provenance.h (status_meanings from beam_sweep_code_meanings()).
// NaN in a stored float dataset means "no solution" (flagged by status = 1), except in
// /stability_margin, where it means "not judged" (flagged by /stability 3 or 4).
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {

// Status codes stored in /status.
inline constexpr int kSweepConverged = 0;
inline constexpr int kSweepNotConverged = 1;

// Result of one point as reported by the method.
struct BeamSweepPoint : SolveStatus {
  TipPose tip;
  // PRBM: 1 when the PRB angle is within the element's validity limit, 0 outside; -1 for a method
  // without validity limits (the exact methods).
  int within_validity = -1;
  // The load alpha2 at this point: the given one (forward), the one found (inverse: a tip angle
  // or deflection given), NaN if none was found. Stored whether or not the point converged.
  double alpha2 = std::numeric_limits<double>::quiet_NaN();
  // The verdict of the point's equilibrium (its message is not stored).
  StabilityKind stability = StabilityKind::kNotChecked;
  int stability_index = 0;
  double stability_margin = 0.0;
  // message: why it failed (only needed when !converged)
};

// The code stored in /stability for a verdict: the order of StabilityKind (0 stable ... 4
// not_checked).
int stability_code(StabilityKind kind);

// Solves one load alpha2; must be safe to call from several threads at once. May throw
// NoConvergence (stored as status 1) or InvalidInput (aborts the sweep).
using BeamPointSolver = std::function<BeamSweepPoint(double alpha2)>;
// Solves point `index` of a sweep (a grid, row-major); the same contract.
using BeamIndexSolver = std::function<BeamSweepPoint(long index)>;

struct BeamSweepOptions {
  int threads = 2;    // worker threads including the caller; 1 = serial
  long chunk = 2048;  // loads handed to a thread at a time (amortises synchronisation)
  // Under mpirun, the fewest loads in a block given to a rank (stream_beam_sweep; the last block
  // may hold fewer): about a millisecond of work, e.g. 1024 loads of a microsecond each.
  long min_block = 1;
  // Called on the calling thread with the number of points done so far (may be null).
  std::function<void(long done, long total)> progress;
  // Names point `index` in an error message, e.g. "alpha2 = 2.5, n = 1" (null: "point 17").
  std::function<std::string(long index)> describe;
};

struct BeamSweepTable {
  std::vector<double> alpha2;
  std::vector<double> a_over_l;
  std::vector<double> b_over_l;
  std::vector<double> theta0;
  std::vector<int> status;
  std::vector<int> within_validity;  // per point as BeamSweepPoint::within_validity (-1 if failed)
  std::vector<int> stability;        // stability_code(); 4 (not_checked) where status != 0
  std::vector<int> stability_index;  // -1 where not judged
  std::vector<double> stability_margin;  // NaN where not judged
  long converged_count = 0;
  long first_failure = -1;            // index of the first point with status != 0, or -1
  std::string first_failure_message;  // the method's message for that point
};

// Solves every load in `alpha2`. Non-converged points (or converged ones with a non-finite
// value) get status 1 and NaN values. Rethrows the first InvalidInput, naming the load.
BeamSweepTable run_beam_sweep(const std::vector<double>& alpha2,
                              const BeamPointSolver& solve,
                              const BeamSweepOptions& options = {});
// The same over `count` points of any sweep; table.alpha2 holds each point's
// BeamSweepPoint::alpha2.
BeamSweepTable run_beam_sweep(long count,
                              const BeamIndexSolver& solve,
                              const BeamSweepOptions& options = {});

// One axis of a sweep, stored as /axes/<name> (1-D): `count` equally spaced values from start to
// stop (solver/common/evenly_spaced.h), generated while writing.
struct BeamSweepAxis {
  std::string name;  // alpha2, load_ratio_n, mu, theta0 or b_over_l
  double start = 0.0;
  double stop = 0.0;
  long count = 1;
  std::string units;
  std::string description;
};

// What produced the table, stored as attributes.
struct BeamSweepMetadata {
  BeamMethod method = BeamMethod::kAuto;  // the method that solved it (attribute "method")
  double load_ratio_n = 0.0;              // stored when it is not an axis
  double mu = 0.0;                        // stored when it is not an axis
  double tolerance = 0.0;
  // The axes in order: the datasets are shaped by their counts (one axis: 1-D; two: a grid,
  // row-major). Empty: a 1-D sweep over the table's alpha2 (the layout above, no /axes group;
  // /alpha2 is then the axis).
  std::vector<BeamSweepAxis> axes;
  // What each point was given: "alpha2" (forward), "theta0" or "b_over_l" (inverse), and its
  // value when it is not an axis (root attribute given_value).
  std::string given = "alpha2";
  double given_value = 0.0;
};

// The meanings of the codes in /status, /within_validity and /stability.
const std::vector<CodeMeaning>& beam_sweep_code_meanings();

// Writes the layout above into `group` (the root of an AtomicHdf5File) as the sweep is solved:
// the datasets are created whole, filled block by block, and the attributes and provenance are
// written by finish().
class BeamSweepWriter {
 public:
  BeamSweepWriter(Hdf5Group& group,
                  long count,
                  const BeamSweepMetadata& metadata,
                  const Hdf5DatasetOptions& options = {});
  // Points [begin, begin + block size) from a table of that block.
  void write(long begin, const BeamSweepTable& block);
  // The attributes and provenance; once, after the last block.
  void finish(long converged_count);

 private:
  Hdf5Group& group_;
  long count_;
  BeamSweepMetadata metadata_;
  Hdf5Dataset alpha2_, a_over_l_, b_over_l_, theta0_, status_, within_validity_, stability_,
      stability_index_, stability_margin_;
};

// The whole table at once (the same file as a streamed sweep).
void write_beam_sweep(Hdf5Group& group,
                      const BeamSweepTable& table,
                      const BeamSweepMetadata& metadata,
                      const Hdf5DatasetOptions& options = {});

// What a streamed sweep found.
struct BeamSweepSummary {
  long count = 0;
  long converged_count = 0;
  long first_failure = -1;            // index of the first point with status != 0, or -1
  std::string first_failure_message;  // the method's message for that point
};

// Solves `count` points in blocks of `block_points` (each on options.threads) and writes every
// block to `writer` before solving the next, so that memory does not grow with count; then calls
// writer.finish(). Progress (options.progress) counts over the whole sweep.
BeamSweepSummary stream_beam_sweep(long count,
                                   const BeamIndexSolver& solve,
                                   const BeamSweepOptions& options,
                                   BeamSweepWriter& writer,
                                   long block_points = 65536);

}  // namespace flexure::io
