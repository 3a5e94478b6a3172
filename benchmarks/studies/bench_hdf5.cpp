#include "flexure/benchmarks/studies/bench_hdf5.h"

#include <fmt/format.h>
#include <hdf5.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <thread>

#include "flexure/benchmarks/studies/bench_run.h"
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure::bench {
namespace {

using io::Hdf5Error;

// Closes an HDF5 handle with the matching H5?close when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

hid_t check(hid_t id, const std::string& what) {
  if (id < 0) throw Hdf5Error(what);
  return id;
}

// A dataset opened for reading, with its number of elements.
struct OpenDataset {
  OpenDataset(hid_t group, const std::string& name, const std::string& where)
      : set(check(H5Dopen2(group, name.c_str(), H5P_DEFAULT),
                  where + ": missing dataset '" + name + "'"),
            H5Dclose),
        space(check(H5Dget_space(set.get()), where + "/" + name + ": no dataspace"), H5Sclose),
        count(H5Sget_simple_extent_npoints(space.get())) {}
  Handle set;
  Handle space;
  hssize_t count;
};

std::vector<std::string> child_names(hid_t group, const std::string& where) {
  std::vector<std::string> names;
  auto collect = [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->push_back(name);
    return 0;
  };
  if (H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names) < 0) {
    throw Hdf5Error(where + ": cannot list the members");
  }
  return names;
}

bool is_group(hid_t parent, const std::string& name) {
  H5O_info_t info;
  if (H5Oget_info_by_name2(parent, name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0) {
    return false;
  }
  return info.type == H5O_TYPE_GROUP;
}

template <typename T>
std::vector<T> read_numeric(hid_t group,
                            const std::string& name,
                            hid_t mem_type,
                            const std::string& where) {
  const OpenDataset data(group, name, where);
  const Handle& set = data.set;
  const hssize_t count = data.count;
  if (count < 0) throw Hdf5Error(where + "/" + name + ": bad dataspace");
  std::vector<T> values(static_cast<std::size_t>(count));
  if (count > 0 && H5Dread(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    throw Hdf5Error(where + "/" + name + ": read failed");
  }
  return values;
}

std::vector<std::string> read_strings(hid_t group,
                                      const std::string& name,
                                      const std::string& where) {
  const OpenDataset data(group, name, where);
  const Handle& set = data.set;
  const hssize_t count = data.count;
  const Handle type(check(H5Tcopy(H5T_C_S1), "string type"), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  std::vector<char*> raw(static_cast<std::size_t>(std::max<hssize_t>(count, 0)), nullptr);
  if (count > 0 && H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()) < 0) {
    throw Hdf5Error(where + "/" + name + ": read failed");
  }
  std::vector<std::string> out;
  for (char* s : raw) {
    out.emplace_back(s ? s : "");
    if (s) H5free_memory(s);
  }
  return out;
}

std::string read_string_attribute(hid_t object, const std::string& name, const std::string& where) {
  const Handle attr(check(H5Aopen(object, name.c_str(), H5P_DEFAULT),
                          where + ": missing attribute '" + name + "'"),
                    H5Aclose);
  const Handle type(check(H5Tcopy(H5T_C_S1), "string type"), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  char* value = nullptr;
  if (H5Aread(attr.get(), type.get(), &value) < 0) {
    throw Hdf5Error(where + ": attribute '" + name + "' is not a string");
  }
  std::string out = value ? value : "";
  if (value) H5free_memory(value);
  return out;
}

template <typename T>
T read_scalar_attribute(hid_t object,
                        const std::string& name,
                        hid_t mem_type,
                        const std::string& where) {
  const Handle attr(check(H5Aopen(object, name.c_str(), H5P_DEFAULT),
                          where + ": missing attribute '" + name + "'"),
                    H5Aclose);
  T value{};
  if (H5Aread(attr.get(), mem_type, &value) < 0) {
    throw Hdf5Error(where + ": attribute '" + name + "' cannot be read");
  }
  return value;
}

void write_run(io::Hdf5Group& problem_group, const MethodRun& run) {
  io::Hdf5Group g = problem_group.create_group(run.method);
  g.set_attribute("family", run.family);
  g.set_attribute("backend", run.backend);
  g.set_attribute("tolerance", run.tolerance);
  g.set_attribute("elements", static_cast<std::int64_t>(run.elements));
  g.set_attribute("increments", static_cast<std::int64_t>(run.increments));
  // The group's statistics, as `bench` prints them; NaN where they cover no point.
  const RunStatistics stats = run_statistics(run);
  g.set_attribute("converged_points", static_cast<std::int64_t>(stats.converged));
  g.set_attribute("measured_points", static_cast<std::int64_t>(stats.measured));
  g.set_attribute("max_relative_error", stats.max_relative_error);
  g.set_attribute("median_seconds", stats.median_seconds);
  // The beam problems are nondimensional (l = 1, EI = 1); cfm_stroke is a mechanism in SI units
  // whose beam columns are present but NaN (docs/hdf5-schema.md).
  const bool mechanism = !run.displacement.empty();
  const std::string nan_here = mechanism ? " (NaN: a mechanism problem)" : "";
  const auto d = [&](const char* name,
                     const std::vector<double>& v,
                     const char* units,
                     const std::string& what) {
    g.write_dataset(name, std::span<const double>(v), units, what);
  };
  const auto i =
      [&](const char* name, const std::vector<int>& v, const char* units, const std::string& what) {
        g.write_dataset(name, std::span<const int>(v), units, what);
      };
  d("load_ratio_n",
    run.load_ratio_n,
    "1",
    "input: load ratio n, horizontal force -n P (compressive for n > 0)" + nan_here);
  d("alpha2", run.alpha2, "1", "input: load alpha2 = P l^2/EI" + nan_here);
  d("mu", run.mu, "1", "input: end moment mu = M l/EI" + nan_here);
  d("a_over_l", run.a_over_l, "1", "output: tip x a/l; NaN unless status is 0 or 3" + nan_here);
  d("b_over_l", run.b_over_l, "1", "output: tip y b/l; NaN unless status is 0 or 3" + nan_here);
  d("theta0", run.theta0, "rad", "output: tip angle; NaN unless status is 0 or 3" + nan_here);
  d("error_position",
    run.error_position,
    "1",
    "|tip - reference tip| / l; NaN without both solutions" + nan_here);
  d("error_relative",
    run.error_relative,
    "1",
    mechanism ? std::string("equal to error_force (so that charts of every problem work)")
              : std::string("error_position / |reference tip displacement from (1, 0)|"));
  d("error_theta0",
    run.error_theta0,
    "rad",
    "|theta0 - reference theta0|; NaN without both solutions" + nan_here);
  d("seconds", run.seconds, "s", "median wall time of one solve over `repeats` solves, one thread");
  i("repeats", run.repeats, "1", "number of timed solves");
  i("status", run.status, "1", "outcome per load (root status_meanings)");
  i("iterations", run.iterations, "1", "the solver's own iteration count");
  i("within_validity",
    run.inside_validity,
    "1",
    "PRBM: 1 within min(Theta_max(gamma), Theta_max(K_theta)), 0 outside; -1 other methods");
  if (!run.reference_source.empty()) {
    i("reference_source",
      run.reference_source,
      "1",
      "which solver gave the reference at this load (root status_meanings)");
  }
  if (mechanism) {
    d("displacement", run.displacement, "m", "input: slider displacement Delta x");
    d("force",
      run.force,
      "N",
      "output: slider input force (positive pushes inward); NaN unless status is 0 or 3");
    d("error_force", run.error_force, "1", "|force - reference force| / |reference force|");
  }
  g.write_dataset("message", run.message, "text", "empty when converged, else the solver's reason");
}

MethodRun read_run(hid_t group,
                   const std::string& problem,
                   const std::string& method,
                   const std::string& where) {
  MethodRun r;
  r.problem = problem;
  r.method = method;
  r.family = read_string_attribute(group, "family", where);
  r.backend = read_string_attribute(group, "backend", where);
  r.tolerance = read_scalar_attribute<double>(group, "tolerance", H5T_NATIVE_DOUBLE, where);
  r.elements = static_cast<int>(
      read_scalar_attribute<std::int64_t>(group, "elements", H5T_NATIVE_INT64, where));
  r.increments = static_cast<int>(
      read_scalar_attribute<std::int64_t>(group, "increments", H5T_NATIVE_INT64, where));
  auto d = [&](const char* name) {
    return read_numeric<double>(group, name, H5T_NATIVE_DOUBLE, where);
  };
  auto i = [&](const char* name) { return read_numeric<int>(group, name, H5T_NATIVE_INT, where); };
  r.load_ratio_n = d("load_ratio_n");
  r.alpha2 = d("alpha2");
  r.mu = d("mu");
  r.a_over_l = d("a_over_l");
  r.b_over_l = d("b_over_l");
  r.theta0 = d("theta0");
  r.error_position = d("error_position");
  r.error_relative = d("error_relative");
  r.error_theta0 = d("error_theta0");
  r.seconds = d("seconds");
  r.repeats = i("repeats");
  r.status = i("status");
  r.iterations = i("iterations");
  // Files before schema 2 called it inside_validity (a checkpoint may be that old).
  r.inside_validity = i(H5Lexists(group, "within_validity", H5P_DEFAULT) > 0 ? "within_validity"
                                                                             : "inside_validity");
  if (H5Lexists(group, "reference_source", H5P_DEFAULT) > 0) {
    r.reference_source = i("reference_source");
  }
  if (H5Lexists(group, "displacement", H5P_DEFAULT) > 0) {
    r.displacement = d("displacement");
    r.force = d("force");
    r.error_force = d("error_force");
  }
  r.message = read_strings(group, "message", where);
  return r;
}

// Every code of the datasets status, within_validity and reference_source (bench_types.h).
const std::vector<io::CodeMeaning>& bench_code_meanings() {
  static const std::vector<io::CodeMeaning> codes = {
      {"status", kStatusConverged, "converged; the error against the reference is measured"},
      {"status", kStatusNotConverged, "the solver returned \"not converged\""},
      {"status", kStatusError, "the solver refused or threw (e.g. no PRBM constants for this n)"},
      {"status", kStatusNoReference, "converged, but the reference failed at this load (no error)"},
      {"within_validity", -1, "not a PRBM method (no validity limit)"},
      {"within_validity", 0, "PRBM: the PRB angle is outside its validity limit"},
      {"within_validity", 1, "PRBM: the PRB angle is within its validity limit"},
      {"reference_source", 0, "the elliptic solver"},
      {"reference_source", 1, "shooting on CVODES at rtol 1e-12, atol 1e-14"},
      {"reference_source", 2, "the exact mechanism model (cfm_stroke)"}};
  return codes;
}

}  // namespace

void write_bench_file(const std::string& path,
                      const BenchFileInfo& info,
                      const std::vector<BenchProblem>& problems,
                      const std::vector<MethodRun>& runs) {
  io::AtomicHdf5File file(path);
  io::Hdf5Group& root = file.root();
  root.set_attribute("schema", "flexure-bench 2 (docs/hdf5-schema.md)");
  root.set_attribute("machine", info.machine);
  root.set_attribute("quick", static_cast<std::int64_t>(info.quick ? 1 : 0));
  root.set_attribute("complete", static_cast<std::int64_t>(info.complete ? 1 : 0));
  root.set_attribute("reference",
                     "elliptic solver (tolerance 1e-14) where it applies and converges, else "
                     "shooting on CVODES at rtol 1e-12, atol 1e-14; cfm_stroke: the exact "
                     "mechanism model (ExactMechanismSolver, shooting rtol 1e-12); per load in "
                     "<problem>/reference/reference_source");
  root.set_attribute("timing", "seconds = median wall time of `repeats` solves, one thread");
  io::write_provenance(root, bench_code_meanings());
  for (const BenchProblem& p : problems) {
    bool any = false;
    for (const MethodRun& r : runs) any = any || r.problem == p.name;
    if (!any) continue;
    io::Hdf5Group pg = root.create_group(p.name);
    pg.set_attribute("description", p.description);
    pg.set_attribute("boundary", p.is_mechanism() ? "mechanism" : to_string(p.boundary));
    if (p.is_mechanism()) pg.set_attribute("mechanism", p.mechanism);
    pg.set_attribute("load_points", static_cast<std::int64_t>(p.points.size()));
    for (const MethodRun& r : runs) {
      if (r.problem == p.name) write_run(pg, r);
    }
  }
  file.commit();
}

std::vector<MethodRun> read_bench_runs(const std::string& path) {
  io::disable_hdf5_error_printing();
  const Handle file(
      check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path + ": cannot open as HDF5"),
      H5Fclose);
  std::vector<MethodRun> runs;
  for (const std::string& problem : child_names(file.get(), path)) {
    if (!is_group(file.get(), problem)) continue;
    const Handle pg(check(H5Gopen2(file.get(), problem.c_str(), H5P_DEFAULT),
                          path + ":/" + problem + ": cannot open"),
                    H5Gclose);
    for (const std::string& method : child_names(pg.get(), path + ":/" + problem)) {
      if (!is_group(pg.get(), method)) continue;
      const std::string where = path + ":/" + problem + "/" + method;
      const Handle mg(check(H5Gopen2(pg.get(), method.c_str(), H5P_DEFAULT), where), H5Gclose);
      runs.push_back(read_run(mg.get(), problem, method, where));
    }
  }
  return runs;
}

bool read_bench_quick_flag(const std::string& path) {
  io::disable_hdf5_error_printing();
  const Handle file(
      check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path + ": cannot open as HDF5"),
      H5Fclose);
  return read_scalar_attribute<std::int64_t>(file.get(), "quick", H5T_NATIVE_INT64, path) != 0;
}

std::string describe_machine() {
  char host[256] = {0};
  if (gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
  struct utsname u {};
  std::string os = "unknown OS";
  if (uname(&u) == 0) os = fmt::format("{} {} {}", u.sysname, u.release, u.machine);
  return fmt::format("{}; {}; {} hardware threads", host, os, std::thread::hardware_concurrency());
}

}  // namespace flexure::bench
