#pragma once
// `flexure path`: the equilibrium path of a beam or segment chain from the unloaded state, by
// pseudo-arclength continuation (shooting: folds and bifurcations located, a bifurcated branch
// followed on request, displacement control, shapes) or by the chain algorithm's load increments,
// as a table of path points and special points, and its HDF5 file (docs/hdf5-schema.md
// "flexure path", docs/cli.md "flexure path").
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flexure/benchmarks/studies/shapes_group.h"
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

// How the numbers of a path are reported: lengths, forces and moments of the chain (l = 1, EI = 1
// for Howell's nondimensional beam) times these factors, in these units.
struct PathUnits {
  std::string system = "nondimensional";  // "nondimensional", "SI" or "chain file"
  double length = 1.0;                    // chain length unit -> reported length unit
  double force = 1.0;
  double moment = 1.0;
  std::string length_unit = "1";
  std::string force_unit = "1";
  std::string moment_unit = "1";
  // Howell's nondimensional beam; a physical beam of length L and rigidity EI in SI (m, N, N m);
  // a chain file in its own units, or in SI (m, N, N m) when the file is physical (units = "SI"
  // or a value written with a unit; io/toml_files.h).
  static PathUnits nondimensional() { return {}; }
  static PathUnits si(double length_m, double EI_Nm2);
  static PathUnits chain_file(bool physical = false);
};

// kBcm, kCbcm: the ladder's beam-constraint models under displacement control (cbcm_path.h; kBcm
// is one element, valid to a transverse deflection of about 0.1 L).
enum class PathMethod { kShooting, kChain, kBcm, kCbcm };
// "shooting", "chain", "bcm", "cbcm" (the --method name, the file's method attribute).
const char* to_string(PathMethod method);

struct PathRequest {
  SegmentChain chain;  // the full-load problem (lambda = 1)
  PathMethod method = PathMethod::kShooting;
  PathUnits units;
  // Chain algorithm: elements and load increments; the CBCM: elements (the BCM: 1).
  int elements = 100;
  int increments = 10;
  // Shooting (continuation.h): 0 = the defaults.
  double max_step = 0.0;  // > 0: largest arclength step (scaled variables; default 0.5)
  int min_points = 0;     // >= 2: at least this many points from zero to full load (the load
                          // factor changes by at most 1/(min_points - 1) per step)
  int branch = 0;         // k > 0: switch onto the other branch at the k-th bifurcation
  int branch_side = 1;    // +1: the half-branch on which the tip moves to +y (+theta), -1: -y
  std::optional<DisplacementControl> control;  // a tip coordinate as the path parameter
  int shape_points = 0;  // >= 2: the shape at every point of the path, at this many points
  // The section at each shape point (shape_points entries, SI: I/c in m^3, area in m^2) for the
  // fibre stresses N/A -+ m c/I stored in /shapes; empty where the section is not known
  // (PhysicalCantilever::fibre_sections).
  std::vector<double> shape_section_modulus, shape_area;
  // The stability verdict of every point under the path's control (docs/stability.md, "Points
  // of a path"): shooting only; the chain algorithm's path records tips only, and only its last
  // point (its answer) is judged.
  bool judge_stability = true;
  StabilityOptions stability;

  // Throws InvalidInput naming the field: a step that is not finite and positive, too few points,
  // a negative branch, shapes or options the chain algorithm does not have, ...
  void validate() const;
};

// A located fold (limit point) or bifurcation, in the units of the table.
struct PathSpecialPoint {
  // Its name ("limit_point", "bifurcation"): to_string (shooting_solver.h).
  SpecialPointKind kind = SpecialPointKind::kLimitPoint;
  double load_factor = 0.0;
  int index = -1;        // row of the path table holding the point itself (-1: not stored)
  int index_after = -1;  // first row after it (-1: none, the path stopped there)
  double tip_x = 0.0, tip_y = 0.0, tip_theta = 0.0;
  double reaction_Fx = 0.0, reaction_Fy = 0.0, reaction_M = 0.0;
  double tip_Fx = 0.0, tip_Fy = 0.0, tip_M = 0.0;
  int stage = 1;
  int branch = 0;
  bool located = true;    // false: not refined; the load factor is that of the nearer point
  bool switched = false;  // the path left here onto the other branch
};

// A zero or extremum of the support's force on the moved coordinate of a displacement-controlled
// path (ForcePoint, control_points.h), in the units of the table.
struct PathForcePoint {
  // Its name ("force_zero", "force_maximum", "force_minimum"): to_string (shooting_solver.h).
  ForcePointKind kind = ForcePointKind::kZero;
  double load_factor = 0.0;  // path parameter (fraction moved)
  double coordinate = 0.0;   // the moved coordinate (length unit, or rad)
  double force = 0.0;        // the support's load on it (force unit, or moment unit)
  double slope = 0.0;        // at a zero: d force / d coordinate (NaN: not computed); else 0
  double tip_x = 0.0, tip_y = 0.0, tip_theta = 0.0;
  double reaction_Fx = 0.0, reaction_Fy = 0.0, reaction_M = 0.0;
  double tip_Fx = 0.0, tip_Fy = 0.0, tip_M = 0.0;
  int index_before = -1;  // the path row before it
  int stage = 1;
  int branch = 0;
  bool located = true;
};

// Consecutive path points with one verdict (the same kind and index): where the state on the
// path is stable, unstable, critical (a located limit or bifurcation point) or not judged.
struct StabilityStretch {
  StabilityKind kind = StabilityKind::kNotChecked;
  int index = 0;            // negative directions (judged kinds only)
  int first = 0, last = 0;  // rows of the path table
  double first_load_factor = 0.0, last_load_factor = 0.0;
};

// The columns of a path file (one row per path point) and what the path did.
struct PathTable {
  std::vector<double> load_factor, tip_x, tip_y, tip_theta;
  std::vector<double> reaction_Fx, reaction_Fy, reaction_M;  // the clamp on the chain
  std::vector<double> tip_Fx, tip_Fy, tip_M;                 // total load on the tip
  std::vector<int> status;  // PathStatus codes: 0 start, 1 accepted, 2 limit point, 3 end,
                            // 4 bifurcation
  std::vector<int> stage;   // 1, or the stage of a staged path
  std::vector<int> branch;  // 0 on the path from zero load; k after switching
  std::vector<PathSpecialPoint> special_points;
  // Displacement control: zeros and extrema of the force on the moved coordinate, in path order.
  std::vector<PathForcePoint> force_points;
  // The verdict of each point under the path's control (PathRequest::judge_stability).
  std::vector<Stability> stability;
  // Shapes (shape_points > 0): rows = path points, columns = shape points, row-major.
  int shape_points = 0;
  std::vector<double> shape_s, shape_x, shape_y, shape_theta, shape_moment;
  // The internal force N (the part beyond s on the part before it) on the tangent and on the
  // normal left of it, N . t and N . n (dm/ds = -V; docs/units.md "Internal forces"): the total
  // tip load at every s; with distributed or joint loads from the statics of the part before s
  // (shape_internal_forces), stored where its moment equals the solver's at every point.
  std::vector<double> shape_axial, shape_shear;
  // The fibre stresses N/A -+ m c/I at the fibres h/2 along +n and -n (Pa), where the section is
  // known (PathRequest::shape_section_modulus) and the internal forces are stored.
  std::vector<double> shape_stress_pos, shape_stress_neg;

  PathMethod method = PathMethod::kShooting;
  PathUnits units;
  std::string boundary;          // end condition
  std::string control = "load";  // "load" (proportional loading) or the controlled coordinate
  double control_target = 0.0;
  bool completed = false;
  double lambda_reached = 0.0;
  int limit_points = 0;
  int bifurcation_points = 0;
  std::optional<double> first_limit_load_factor;
  bool switched_branch = false;
  int steps = 0;
  int rejected_steps = 0;
  int newton_iterations = 0;
  int location_corrections = 0;
  std::string message;
  // The BCM's path stopped where its element left the BCM's stated range (|y| > 0.1 of its
  // length): the points up to there are within it (the CLI's exit code 2, OutsideMethodDomain).
  bool left_domain = false;
  int elements = 0;  // bcm, cbcm: the elements N
  // One line per bifurcation passed (not switched at): where, and what it means for the state on
  // the path (for the text output and stderr).
  std::vector<std::string> warnings;

  std::size_t size() const { return load_factor.size(); }
  std::vector<const PathSpecialPoint*> of_kind(SpecialPointKind kind) const;
  std::vector<StabilityStretch> stability_stretches() const;
};

// "stable at points 0-12 (load factor 0 to 0.8224670334)", "unstable (index 1) at points ...":
// one stretch in words (text output).
std::string describe(const StabilityStretch& s);

// Runs the path. Throws InvalidInput for bad input; a path that stops before the full load
// returns completed == false with the message (the table holds the path up to there).
PathTable run_load_path(const PathRequest& request);

// The codes of the `status`, `special_points/located` and `special_points/switched` datasets (root
// attribute status_meanings).
const std::vector<io::CodeMeaning>& path_code_meanings();

// The table's shapes as the shared /shapes writer takes them (shapes_group.h); views into `table`.
ShapesView path_shapes_view(const PathTable& table);

// Writes the table to `root` (datasets, /special_points, /shapes, attributes and provenance;
// docs/hdf5-schema.md "flexure path").
void write_path_file(io::Hdf5Group& root, const PathTable& table);

// The HDF5 file of `flexure path`, opened when the writer is made so that a path that cannot be
// written fails before the path is solved (exit 2), and appearing whole or not at all
// (AtomicHdf5File): write() fills it with write_path_file and commits it; a writer destroyed
// before write() leaves nothing behind.
class PathFile {
 public:
  // Creates the temporary file next to `path`. Throws InvalidInput "<shown_as>: <why>" when the
  // file cannot be written there (`shown_as` names the file as the user gave it, e.g. "--out
  // x.csv" when `path` is the hidden HDF5 file behind a CSV table).
  PathFile(const std::string& path, const std::string& shown_as);
  ~PathFile();
  PathFile(PathFile&&) noexcept;
  PathFile& operator=(PathFile&&) noexcept;

  // Writes the table and renames the file into place. Once only.
  void write(const PathTable& table);

 private:
  std::string path_;
  std::unique_ptr<io::AtomicHdf5File> file_;
};

}  // namespace flexure
