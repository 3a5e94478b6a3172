#pragma once
// The run of `flexure sweep beam` (docs/cli.md, docs/hdf5-schema.md "flexure sweep beam"): the
// scheduling policy (how many points, threads, chunks and blocks) and the file, streamed block by
// block so that memory stays flat. The command line parses the flags into a BeamSweepGrid and
// calls this; the library decides everything else.
//
// The file is opened when the BeamSweepFile is made, so that a path that cannot be written fails
// before any point is solved, and it appears whole or not at all (io/platform/hdf5_file.h
// AtomicHdf5File). Under mpirun every rank writes its blocks into the one file (docs/scaling.md).
// No HDF5 type is visible here.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/beam_sweep_grid.h"

namespace flexure {
namespace io {
class AtomicHdf5File;
struct BeamSweepAxis;
}  // namespace io

// The most points a sweep may have: 10^7 (a file of about 400 MB), under mpirun 10^10 (the studies
// of docs/scaling.md, 10^9 points: 40 GB). The sweep streams, so memory stays flat either way.
long max_beam_sweep_points();

// Worker threads per process when the caller names none: 2, and under mpirun 1 per rank (the
// ranks are the parallelism).
int default_beam_sweep_threads();

// Points handed to a thread at a time: about 1/64 of each thread's share, so that progress moves
// steadily on slow methods, at most 2048, which amortises the hand-out on fast ones.
long beam_sweep_chunk(long count, int threads);

// Under mpirun, the fewest points in a rank's block: the elliptic solve and the PRBM take about a
// microsecond per load, so a block holds at least 1024 (a message and a write worth their cost);
// the other methods take milliseconds, and their blocks shrink to single loads at the end.
long beam_sweep_min_block(BeamMethod method);

// "alpha2 = 2.5, load_ratio_n = 1": point `index` of the grid, for messages.
std::string describe_sweep_point(const BeamSweepGrid& grid, long index);

// The most values (points x shape points) the shapes of a sweep may hold: 5 * 10^6. The shapes are
// kept in memory until the sweep ends (up to nine datasets of 8-byte values: about 360 MB).
long max_beam_sweep_shape_values();

// Throws InvalidInput when `shape_points` shape points at each of `count` points is not a request
// a sweep takes: shape_points outside [2, 100000], more values than max_beam_sweep_shape_values(),
// or under mpirun with several ranks (the shapes are gathered in one process). 0: no shapes, fine.
void check_beam_sweep_shapes(long count, int shape_points);

struct BeamSweepRunOptions {
  int threads = 0;  // 0: default_beam_sweep_threads(); else 1..64
  // >= 2: the deformed shape of every point at this many equally spaced arc lengths, stored in
  // /shapes with the internal forces (docs/hdf5-schema.md "flexure sweep beam"), and the XDMF
  // sidecar next to the file. 0: none. Every point is then solved from zero load (no warm start).
  int shape_points = 0;
  // Called on the calling thread with the points done so far (may be null).
  std::function<void(long done, long total)> progress;
};

// What a run found. `axes`: the axes stored under /axes (none for the plain sweep over alpha2,
// whose /alpha2 is the axis).
struct BeamSweepRun {
  long count = 0;
  long converged_count = 0;
  BeamMethod method = BeamMethod::kElliptic;  // what the requested method resolved to
  long first_failure = -1;                    // index of the first point not converged, or -1
  std::string first_failure_message;          // the method's message for that point
  std::vector<std::string> stored_axes;       // names under /axes, in the datasets' axis order
  std::string xdmf;                           // the XDMF sidecar of the shapes (empty: none)
};

class BeamSweepFile {
 public:
  // Creates the temporary file next to `path` (collectively under mpirun). Throws InvalidInput
  // "OPTION: reason" (the caller's name for the file, "--out" for the tool) when it cannot be
  // written there, and for `compress` under mpirun with several ranks (parallel HDF5 writes
  // compressed datasets only collectively; the tool refuses its flag first).
  BeamSweepFile(const std::string& path, bool compress, const std::string& option = "--out");
  ~BeamSweepFile();
  BeamSweepFile(BeamSweepFile&&) noexcept;
  BeamSweepFile& operator=(BeamSweepFile&&) noexcept;

  // Solves every point of `grid` with `method` (auto resolves as for a sweep: elliptic), writes
  // each block before solving the next, and renames the file into place, whatever converged
  // (points without a converged solution are stored with status 1 and NaN). Once only. Throws
  // InvalidInput for a bad thread count, or what a point's solve throws as InvalidInput.
  BeamSweepRun run(const BeamSweepGrid& grid,
                   BeamMethod method,
                   const BeamSweepRunOptions& options = {});

 private:
  std::string path_;
  bool compress_ = false;
  std::unique_ptr<io::AtomicHdf5File> file_;
};

}  // namespace flexure
