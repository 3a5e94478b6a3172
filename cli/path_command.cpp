// `flexure path`: the load path of proportional loading from zero, by pseudo-arclength
// continuation (shooting) or load increments (chain algorithm), written to HDF5.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>

#include "cli/beam_methods.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "flexure/io/chain_toml.h"
#include "flexure/io/hdf5_file.h"
#include "flexure/io/output_path.h"
#include "flexure/io/provenance.h"
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/common/errors.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure::cli {
namespace {

struct PathArgs {
  double load_ratio_n = 0.0;
  double alpha2 = 0.0;
  double mu = 0.0;
  double follower = 0.0;
  std::string boundary = "free";
  double tip_x = 0.0, tip_y = 0.0, tip_angle = 0.0;
  CLI::Option* tip_x_option = nullptr;
  CLI::Option* tip_y_option = nullptr;
  CLI::Option* tip_angle_option = nullptr;
  std::string method = "shooting";
  int elements = 100;
  int increments = 10;
  std::string chain_file;
  CLI::Option* chain_option = nullptr;
  std::string out;
  bool json = false;
};

// The columns of the path file (docs/cli.md, "flexure path").
struct PathTable {
  std::vector<double> load_factor, tip_x, tip_y, tip_theta, reaction_Fx, reaction_Fy, reaction_M;
  std::vector<int> status;  // 0 start, 1 accepted, 2 limit point passed, 3 end (full load)
  bool completed = false;
  double lambda_reached = 0.0;
  int limit_points = 0;
  std::string message;
};

PathTable shooting_path(const SegmentChain& chain) {
  const LoadPath path = trace_load_path(chain, ShootingSolver::Options{});
  PathTable t;
  for (const PathPoint& p : path.points) {
    t.load_factor.push_back(p.lambda);
    t.tip_x.push_back(p.tip.x);
    t.tip_y.push_back(p.tip.y);
    t.tip_theta.push_back(p.tip.theta);
    t.reaction_Fx.push_back(p.reaction.Fx);
    t.reaction_Fy.push_back(p.reaction.Fy);
    t.reaction_M.push_back(p.reaction.M);
    t.status.push_back(static_cast<int>(p.status));
  }
  t.completed = path.converged();
  t.lambda_reached = path.lambda_reached;
  t.limit_points = path.limit_points;
  t.message = path.message;
  return t;
}

PathTable chain_path(const SegmentChain& chain, const PathArgs& args) {
  ChainAlgorithmSolver::Options options;
  options.elements = args.elements;
  options.increments = args.increments;
  options.record_load_path = true;
  const ChainResult r = solve_chain(chain, options);
  PathTable t;
  t.load_factor.push_back(0.0);
  const ChainPose start = chain.unloaded_tip();
  t.tip_x.push_back(start.x);
  t.tip_y.push_back(start.y);
  t.tip_theta.push_back(start.theta);
  t.status.push_back(0);
  for (const ChainLoadPathPoint& p : r.load_path) {
    t.load_factor.push_back(p.load_factor);
    t.tip_x.push_back(p.tip.x);
    t.tip_y.push_back(p.tip.y);
    t.tip_theta.push_back(p.tip.theta);
    t.status.push_back(p.load_factor >= 1.0 ? 3 : 1);
  }
  // The chain algorithm records tip poses per increment; reactions only at the end.
  t.reaction_Fx.assign(t.load_factor.size(), std::nan(""));
  t.reaction_Fy.assign(t.load_factor.size(), std::nan(""));
  t.reaction_M.assign(t.load_factor.size(), std::nan(""));
  t.reaction_Fx.back() = r.root_reaction.Fx;
  t.reaction_Fy.back() = r.root_reaction.Fy;
  t.reaction_M.back() = r.root_reaction.M;
  t.completed = r.converged();
  t.lambda_reached = r.load_factor;
  t.message = r.message;
  return t;
}

// The codes of /status (PathTable::status).
const std::vector<io::CodeMeaning>& path_code_meanings() {
  static const std::vector<io::CodeMeaning> codes = {
      {"status", 0, "start: the unloaded beam (load factor 0)"},
      {"status", 1, "an accepted continuation step or load increment"},
      {"status", 2, "a limit point (fold) of the load factor was passed at this step"},
      {"status", 3, "end: the full load (load factor 1)"}};
  return codes;
}

// The path file (docs/hdf5-schema.md "flexure path"). Without --chain the problem is Howell's
// nondimensional beam (l = 1, EI = 1); a chain file is in whatever consistent units it was written
// in (docs/chain-toml.md), so the units say that instead of guessing.
void write_path_file(io::Hdf5Group& file,
                     const PathTable& t,
                     const PathArgs& args,
                     const SegmentChain& chain) {
  const bool from_file = args.chain_option != nullptr && *args.chain_option;
  const std::string length = from_file ? "length unit of the chain file" : "1";
  const std::string force = from_file ? "force unit of the chain file" : "1";
  const std::string moment = from_file ? "force unit * length unit of the chain file" : "1";
  const std::string scaled = from_file ? "" : " (nondimensional: l = 1, EI = 1)";
  file.write_dataset("load_factor",
                     t.load_factor,
                     "1",
                     "load factor lambda: 0 unloaded, 1 full load; may fall and rise at limit "
                     "points");
  file.write_dataset("tip_x", t.tip_x, length, "tip x along the clamp's axis" + scaled);
  file.write_dataset("tip_y", t.tip_y, length, "tip y perpendicular to the clamp's axis" + scaled);
  file.write_dataset("tip_theta", t.tip_theta, "rad", "tip angle");
  file.write_dataset("reaction_Fx",
                     t.reaction_Fx,
                     force,
                     "x force the clamp exerts" + scaled + "; chain: NaN except at the last point");
  file.write_dataset("reaction_Fy",
                     t.reaction_Fy,
                     force,
                     "y force the clamp exerts" + scaled + "; chain: NaN except at the last point");
  file.write_dataset("reaction_M",
                     t.reaction_M,
                     moment,
                     "moment the clamp exerts" + scaled + "; chain: NaN except at the last point");
  file.write_dataset("status", t.status, "1", "kind of point (root status_meanings)");
  file.set_attribute("method", args.method);
  file.set_attribute("boundary", to_string(chain.end));
  file.set_attribute("completed", static_cast<std::int64_t>(t.completed ? 1 : 0));
  file.set_attribute("load_factor_reached", t.lambda_reached);
  file.set_attribute("limit_points", static_cast<std::int64_t>(t.limit_points));
  file.set_attribute("message", t.message);
  io::write_provenance(file, path_code_meanings());
}

void run_path(const PathArgs& args) {
  BeamProblem problem;
  if (*args.chain_option) {
    problem.chain = io::read_chain_toml(args.chain_file);
  } else {
    require_finite_input(args.load_ratio_n, "--n (load ratio n)");
    require_finite_input(args.alpha2, "--alpha2 (P l^2/EI)");
    require_finite_input(args.mu, "--mu (end moment M l/EI)");
    require_finite_input(args.follower, "--follower (follower force F l^2/EI)");
    problem.load_ratio_n = args.load_ratio_n;
    problem.mu = args.mu;
    problem.follower = args.follower;
    problem.boundary = end_condition_from_string(args.boundary);
    if (*args.tip_x_option) problem.prescribed.x = args.tip_x;
    if (*args.tip_y_option) problem.prescribed.y = args.tip_y;
    if (*args.tip_angle_option) problem.prescribed.theta = args.tip_angle;
  }
  require_in_range(args.elements, "--elements (chain algorithm elements N)", 1, 1'000'000);
  require_in_range(args.increments, "--increments (load increments)", 1, 1'000'000);
  const SegmentChain chain = problem.to_chain(args.alpha2);
  // Check and open the output first: an unwritable path fails before any solving (exit 2).
  io::check_output_path(args.out);
  std::unique_ptr<io::AtomicHdf5File> output;
  try {
    output = std::make_unique<io::AtomicHdf5File>(args.out);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(fmt::format("--out {}: {}", args.out, e.what()));
  }
  io::Hdf5Group& file = output->root();
  const auto start = std::chrono::steady_clock::now();
  const PathTable t = args.method == "chain" ? chain_path(chain, args) : shooting_path(chain);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_path_file(file, t, args, chain);
  output->commit();
  if (args.json) {
    print_json(Json{{"out", args.out},
                    {"method", args.method},
                    {"points", static_cast<long>(t.load_factor.size())},
                    {"completed", t.completed},
                    {"load_factor_reached", t.lambda_reached},
                    {"limit_points", t.limit_points},
                    {"message", t.message},
                    {"seconds", seconds}});
  } else {
    fmt::print("{} load path: {} points, load factor reached {:.6g}, {} limit point(s); {}\n",
               args.method,
               t.load_factor.size(),
               t.lambda_reached,
               t.limit_points,
               t.message);
    fmt::print("written to {}\n", args.out);
  }
  if (!t.completed) {
    throw NoConvergence(fmt::format(
        "the {} load path stopped at load factor {:.6g}: {} (the path up to there is in {})",
        args.method,
        t.lambda_reached,
        t.message,
        args.out));
  }
}

}  // namespace

void register_path_command(CLI::App& app) {
  auto args = std::make_shared<PathArgs>();
  CLI::App* path = app.add_subcommand(
      "path", "Load path of proportional loading from zero (continuation), written to HDF5");
  path->add_option("--n", args->load_ratio_n, "Load ratio n: horizontal load nP, n > 0 compressive")
      ->default_str("0");
  path->add_option("--alpha2", args->alpha2, "Full load alpha2 = P l^2/EI")->default_str("0");
  path->add_option("--mu", args->mu, "End moment mu = M l/EI")->default_str("0");
  path->add_option("--follower", args->follower, "Follower tip force F l^2/EI")->default_str("0");
  path->add_option("--boundary", args->boundary, "free | guided | pinned | slider | fixed")
      ->default_str("free")
      ->transform(CLI::IsMember({"free", "guided", "pinned", "slider", "fixed"}, CLI::ignore_case));
  args->tip_x_option = path->add_option("--tip-x", args->tip_x, "Prescribed tip x/l");
  args->tip_y_option = path->add_option("--tip-y", args->tip_y, "Prescribed tip y/l");
  args->tip_angle_option = path->add_option("--tip-angle", args->tip_angle, "Prescribed tip angle");
  path->add_option("--method", args->method, "shooting (arc-length continuation) | chain")
      ->default_str("shooting")
      ->transform(CLI::IsMember({"shooting", "chain"}, CLI::ignore_case));
  path->add_option("--elements", args->elements, "Chain algorithm: elements N")->default_str("100");
  path->add_option("--increments", args->increments, "Chain algorithm: load increments")
      ->default_str("10");
  args->chain_option =
      path->add_option("--chain", args->chain_file, "Segment chain from a TOML file");
  path->add_option("--out", args->out, "Output HDF5 file (written atomically)")->required();
  path->add_flag("--json", args->json, "Print one JSON summary object on stdout");
  path->callback([args] { run_path(*args); });
}

}  // namespace flexure::cli
