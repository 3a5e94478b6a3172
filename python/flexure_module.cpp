// flexure._core: the compiled half of the Python module (docs/python.md). Entry points:
//  * run(args): one `flexure` command run in-process (cli/command_runner.h) with the lock on the
//    interpreter released, its JSON object converted to Python (arrays of numbers to numpy);
//  * beam(**values): `flexure beam --json` for one load from values, by the library without a
//    command line (BeamRequest, solve_beam, the keys of beam/beam_keys.h; the scalar flexure.beam);
//  * beam_many(keywords, ...): `flexure beam` at many loads on worker threads, columns written
//    straight into numpy arrays (the vectorised flexure.beam);
//  * the classes over the library's types (python/objects.cpp).
// The Python half (python/flexure/*.py) turns keyword arguments into the tool's flags and
// raises the module's exceptions; nothing here decides anything the tool does not.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <toml++/toml.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

#include "cli/beam_command.h"
#include "cli/beam_methods.h"
#include "cli/cli_common.h"
#include "cli/command_runner.h"
#include "flexure/beam/beam_keys.h"
#include "flexure/beam/beam_problem.h"
#include "flexure/beam/beam_request.h"
#include "flexure/solver/common/gsl_guard.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"
#include "flexure/version.h"
#include "python/object_support.h"
#include "python/objects.h"

namespace py = pybind11;

namespace flexure::python {
namespace {

using cli::Json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool is_number_or_null(const Json& j) { return j.is_number() || j.is_null(); }

// An array whose leaves are all numbers or nulls, nested to a uniform depth and length: its shape.
bool numeric_shape(const Json& j, std::vector<py::ssize_t>& shape, std::size_t depth = 0) {
  if (!j.is_array() || j.empty()) return false;
  if (shape.size() == depth) shape.push_back(static_cast<py::ssize_t>(j.size()));
  if (shape[depth] != static_cast<py::ssize_t>(j.size())) return false;
  const bool leaves = is_number_or_null(j.front());
  for (const Json& e : j) {
    if (leaves ? !is_number_or_null(e) : !numeric_shape(e, shape, depth + 1)) return false;
  }
  return leaves ? shape.size() == depth + 1 : true;
}

void flatten(const Json& j, std::vector<double>& out) {
  for (const Json& e : j) {
    if (e.is_array()) {
      flatten(e, out);
    } else {
      out.push_back(e.is_null() ? kNaN : e.get<double>());
    }
  }
}

bool all_integers(const Json& j) {
  for (const Json& e : j) {
    if (e.is_array() ? !all_integers(e) : !e.is_number_integer()) return false;
  }
  return true;
}

// Objects with the same keys whose values are numbers, nulls or booleans (e.g. shape points
// {s, x, y, theta}): stored column by column.
bool is_record_array(const Json& j) {
  if (!j.is_array() || j.empty() || !j.front().is_object() || j.front().empty()) return false;
  const Json& first = j.front();
  for (const Json& e : j) {
    if (!e.is_object() || e.size() != first.size()) return false;
    for (const auto& [key, value] : e.items()) {
      if (!first.contains(key) || !(is_number_or_null(value) || value.is_boolean())) return false;
    }
  }
  return true;
}

py::object to_python(const Json& j);

py::object numeric_array(const Json& j, const std::vector<py::ssize_t>& shape) {
  if (all_integers(j)) {
    std::vector<double> values;
    flatten(j, values);
    py::array_t<long long> a(shape);
    long long* p = a.mutable_data();
    for (std::size_t i = 0; i < values.size(); ++i) p[i] = static_cast<long long>(values[i]);
    return a;
  }
  std::vector<double> values;
  flatten(j, values);
  py::array_t<double> a(shape);
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

// JSON -> Python: objects to dicts (key order kept), arrays of numbers (nested to any uniform
// depth; null -> NaN) to numpy arrays, arrays of booleans to boolean arrays, arrays of records to
// a dict of columns, anything else to lists, str, int, float, bool, None.
py::object to_python(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null:
      return py::none();
    case Json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case Json::value_t::number_integer:
      return py::int_(j.get<long long>());
    case Json::value_t::number_unsigned:
      return py::int_(j.get<unsigned long long>());
    case Json::value_t::number_float:
      return py::float_(j.get<double>());
    case Json::value_t::string:
      return py::str(j.get<std::string>());
    case Json::value_t::object: {
      py::dict d;
      for (const auto& [key, value] : j.items()) d[py::str(key)] = to_python(value);
      return d;
    }
    case Json::value_t::array: {
      std::vector<py::ssize_t> shape;
      if (numeric_shape(j, shape)) return numeric_array(j, shape);
      if (!j.empty() &&
          std::all_of(j.begin(), j.end(), [](const Json& e) { return e.is_boolean(); })) {
        py::array_t<bool> a(static_cast<py::ssize_t>(j.size()));
        for (std::size_t i = 0; i < j.size(); ++i) a.mutable_data()[i] = j[i].get<bool>();
        return a;
      }
      if (is_record_array(j)) {
        py::dict columns;
        for (const auto& [key, ignored] : j.front().items()) {
          Json column = Json::array();
          for (const Json& e : j) column.push_back(e.at(key));
          columns[py::str(key)] = to_python(column);
        }
        return columns;
      }
      py::list l;
      for (const Json& e : j) l.append(to_python(e));
      return l;
    }
    default:
      return py::none();
  }
}

// run(args) -> (kind, payload, warnings, exit_code): kind "ok" (payload: the JSON object),
// "invalid" (InvalidInput: payload the message), "no_convergence" (payload (message, reached)),
// "error" (anything else). The Python half raises the matching exception. With a `bridge`, the
// command's stoppable steps (run_command's progress, cli/command_runner.h) call it: a progress
// callable, and Ctrl-C, which raise their exception here whatever the command did after it
// (python/object_support.h).
template <class Command>
py::tuple run_released(Command&& command, ProgressBridge* bridge = nullptr) {
  cli::CommandOutput out;
  std::string kind = "ok", message;
  Json reached = Json::object();
  {
    py::gil_scoped_release release;
    try {
      out = command();
    } catch (const ProgressBridge::Stopped&) {
      kind = "stopped";  // raised below, with the lock
    } catch (const InvalidInput& e) {
      kind = "invalid";
      message = e.what();
    } catch (const cli::NoConvergenceReport& e) {
      kind = "no_convergence";
      message = e.what();
      reached = e.reached();
    } catch (const NoConvergence& e) {
      kind = "no_convergence";
      message = e.what();
    } catch (const std::exception& e) {
      kind = "error";
      message = e.what();
    }
  }
  if (bridge != nullptr) bridge->raise_if_stopped();
  py::list warnings;
  for (const std::string& w : out.warnings) warnings.append(w);
  if (kind == "ok") return py::make_tuple(kind, to_python(out.json), warnings, out.exit_code);
  return py::make_tuple(kind, py::make_tuple(message, to_python(reached)), warnings, 0);
}

py::tuple run(const std::vector<std::string>& args, py::object progress) {
  ProgressBridge bridge(std::move(progress));
  return run_released(
      [&] {
        return cli::run_command(
            args, [&bridge](std::size_t done, std::size_t total) { bridge(done, total); });
      },
      &bridge);
}

// beam(...): `flexure beam --json` for keyword values, by the library alone, the same result as
// run(["beam", ...]) without a command line (python/flexure/_beam.py decides which applies): the
// request checked by make_beam_input with the tool's names (so its messages), solved, the answer
// checked (require_complete_answer), its warnings (beam_answer_warnings) and its keys written by
// the beam layer's one writer (beam/beam_keys.h), which the command uses too; a failed solve
// reported as the command reports it (cli::throw_beam_failure). A physical beam or a chain file
// goes through run(): the keywords here never give one.
py::tuple beam_request(const BeamRequest& request) {
  return run_released([&] {
    if (request.physical || request.chain) {
      throw std::logic_error("beam: a physical beam or a chain file goes through run()");
    }
    const BeamRequestNames names = BeamRequestNames::command_line();
    cli::CommandOutput out;
    const BeamInput input = make_beam_input(request, names);
    for (const Warning& w : input.warnings) out.warnings.push_back(w.text);
    const BeamProblem& problem = input.problem;
    BeamSolution solution;
    try {
      solution = solve_beam(input.method, problem);
    } catch (const bench::ToleranceBelowReach& e) {
      cli::refuse_tolerance_below_reach(e, problem.tolerance);
    }
    if (!solution.converged()) cli::throw_beam_failure(problem, solution);
    require_complete_answer(problem, solution);
    for (const Warning& w : beam_answer_warnings(problem, solution, names)) {
      out.warnings.push_back(w.text);
    }
    out.json = beam_keys::answer<Json>(input, solution, nullptr, names);
    cli::require_finite_json(out.json);
    return out;
  });
}

// ---- a design given as a dict: TOML text for the tool's file readers ----

// Adds `j` to a TOML table (under `key`) or array through `add`, which takes any TOML value.
template <class Add>
void add_toml(const Json& j, const std::string& where, Add&& add);

toml::array toml_array(const Json& j, const std::string& where) {
  toml::array a;
  for (std::size_t i = 0; i < j.size(); ++i) {
    add_toml(j[i], where + "[" + std::to_string(i) + "]", [&a](auto&& v) {
      a.push_back(std::forward<decltype(v)>(v));
    });
  }
  return a;
}

toml::table toml_table(const Json& j, const std::string& where) {
  toml::table t;
  for (const auto& [key, value] : j.items()) {
    add_toml(value, where + "." + key, [&t, &key](auto&& v) {
      t.insert(key, std::forward<decltype(v)>(v));
    });
  }
  return t;
}

template <class Add>
void add_toml(const Json& j, const std::string& where, Add&& add) {
  switch (j.type()) {
    case Json::value_t::boolean:
      return add(j.get<bool>());
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
      return add(j.get<int64_t>());
    case Json::value_t::number_float:
      return add(j.get<double>());
    case Json::value_t::string:
      return add(j.get<std::string>());
    case Json::value_t::array:
      return add(toml_array(j, where));
    case Json::value_t::object:
      return add(toml_table(j, where));
    default:
      throw InvalidInput(fmt::format("{}: None has no TOML form; leave the key out", where));
  }
}

// toml_text(json) -> the TOML document of a dict given as JSON text (the Python half passes
// json.dumps(d)); InvalidInput (ValueError) for a value TOML cannot hold.
std::string toml_text(const std::string& json_text) {
  const Json j = Json::parse(json_text);
  if (!j.is_object()) throw InvalidInput("a design dict must be a mapping of TOML keys");
  std::ostringstream out;
  out << toml_table(j, "design") << '\n';
  return out.str();
}

// ---- the vectorised beam ----

// Status codes of the vectorised beam (docs/python.md): 0 converged, 1 no converged solution at
// this load (the tool's exit code 3), 2 invalid input at this load (exit code 2).
constexpr int kConverged = 0, kNotConverged = 1, kInvalid = 2;

// A numpy array allocated while the interpreter's lock is held, filled by the workers without it.
// Columns a method never fills (`used` false: PRBM's for the elliptic method, ...) are not
// allocated: at 10^6 loads every column is 8 MB of fresh memory to clear.
template <class T>
struct NumpyColumn {
  NumpyColumn(const std::vector<py::ssize_t>& shape, T initial, bool used = true)
      : array(used ? shape : std::vector<py::ssize_t>{0}) {
    data = array.mutable_data();
    std::fill(data, data + array.size(), initial);
  }
  py::array_t<T> array;
  T* data;
};

// A column of texts, interned per worker without locks: point i holds code = local index *
// workers + worker; most columns hold a few distinct texts, in runs.
class TextColumn {
 public:
  TextColumn(std::size_t count, int workers)
      : codes_(count, 0), texts_(workers), index_(workers), last_(workers, -1) {}
  void set(std::size_t i, int worker, std::string_view text) {
    std::vector<std::string>& texts = texts_[worker];
    long& last = last_[worker];
    if (last < 0 || texts[last] != text) {
      auto [it, added] = index_[worker].try_emplace(std::string(text), texts.size());
      if (added) texts.emplace_back(text);
      last = static_cast<long>(it->second);
    }
    codes_[i] = static_cast<std::uint32_t>(last * static_cast<long>(texts_.size()) + worker);
  }
  // An object array of lists of str: each point's text split at newlines ("" an empty list).
  py::array to_numpy_lists(const std::vector<py::ssize_t>& shape) const {
    const auto workers = static_cast<std::uint32_t>(texts_.size());
    py::array out = py::module_::import("numpy").attr("empty")(shape, py::dtype("O"));
    auto** cells = static_cast<PyObject**>(out.mutable_data());
    for (std::size_t i = 0; i < codes_.size(); ++i) {
      const std::uint32_t w = codes_[i] % workers, k = codes_[i] / workers;
      py::list items;
      if (k < texts_[w].size() && !texts_[w][k].empty()) {
        std::string_view rest = texts_[w][k];
        for (;;) {
          const std::size_t end = rest.find('\n');
          items.append(py::str(std::string(rest.substr(0, end))));
          if (end == std::string_view::npos) break;
          rest.remove_prefix(end + 1);
        }
      }
      Py_XDECREF(cells[i]);  // numpy.empty fills object arrays with None
      cells[i] = items.release().ptr();
    }
    return out;
  }
  // An object array of the JSON texts as the scalar call returns them (to_python; "" is None);
  // equal texts share one object.
  py::array to_numpy_json(const std::vector<py::ssize_t>& shape) const {
    const auto workers = static_cast<std::uint32_t>(texts_.size());
    std::vector<std::vector<py::object>> objects(texts_.size());
    for (std::size_t w = 0; w < texts_.size(); ++w) {
      for (const std::string& text : texts_[w]) {
        objects[w].push_back(text.empty() ? py::none() : to_python(Json::parse(text)));
      }
    }
    py::array out = py::module_::import("numpy").attr("empty")(shape, py::dtype("O"));
    auto** cells = static_cast<PyObject**>(out.mutable_data());
    for (std::size_t i = 0; i < codes_.size(); ++i) {
      const std::uint32_t w = codes_[i] % workers, k = codes_[i] / workers;
      py::object value = k < objects[w].size() ? objects[w][k] : py::none();
      Py_XDECREF(cells[i]);  // numpy.empty fills object arrays with None
      cells[i] = value.release().ptr();
    }
    return out;
  }
  // An object array of str (equal texts share one object); points never set read "".
  py::array to_numpy(const std::vector<py::ssize_t>& shape) const {
    const auto workers = static_cast<std::uint32_t>(texts_.size());
    std::vector<std::vector<py::object>> objects(workers);
    for (std::uint32_t w = 0; w < workers; ++w) {
      for (const std::string& t : texts_[w]) objects[w].push_back(py::str(t));
    }
    const py::str empty("");
    py::array out = py::module_::import("numpy").attr("empty")(shape, py::dtype("O"));
    auto** cells = static_cast<PyObject**>(out.mutable_data());
    for (std::size_t i = 0; i < codes_.size(); ++i) {
      const std::uint32_t w = codes_[i] % workers, k = codes_[i] / workers;
      PyObject* o = k < objects[w].size() ? objects[w][k].ptr() : empty.ptr();
      Py_INCREF(o);
      Py_XDECREF(cells[i]);  // numpy.empty fills object arrays with None
      cells[i] = o;
    }
    return out;
  }

 private:
  std::vector<std::uint32_t> codes_;
  std::vector<std::vector<std::string>> texts_;
  std::vector<std::unordered_map<std::string, std::size_t>> index_;
  std::vector<long> last_;
};

// Which method-specific keys a call may print (auto: all of them).
struct UsedKeys {
  bool prbm = false;    // within_validity, Theta, theta_max, validity_source
  bool chain = false;   // elements, increments
  bool prbm3r = false;  // constants
  bool bcm = false;  // bcm, cbcm: elements, max_element_deflection, within_validity, slenderness,
                     // axial_stiffness_d
};

// The keys of `flexure beam --json` (cli/beam_command.cpp to_json) as columns.
struct Columns {
  Columns(const std::vector<py::ssize_t>& shape, std::size_t count, int workers, UsedKeys used)
      : n(shape, kNaN),
        alpha2(shape, kNaN),
        mu(shape, kNaN),
        a_over_l(shape, kNaN),
        b_over_l(shape, kNaN),
        theta0(shape, kNaN),
        root_moment(shape, kNaN),
        target_residual(shape, kNaN),
        first_limit_load_factor(shape, kNaN),
        reaction_Fx(shape, kNaN),
        reaction_Fy(shape, kNaN),
        reaction_M(shape, kNaN),
        stability_index(shape, kNaN),
        stability_margin(shape, kNaN),
        Theta(shape, kNaN, used.prbm),
        theta_max(shape, kNaN, used.prbm),
        expected_error(shape, kNaN),
        expected_error_per_length(shape, kNaN),
        max_element_deflection(shape, kNaN, used.bcm),
        slenderness(shape, kNaN, used.bcm),
        axial_stiffness_d(shape, kNaN, used.bcm),
        iterations(shape, 0),
        inflection_points(shape, 0),
        limit_points(shape, 0),
        elements(shape, 0, used.chain || used.bcm),
        increments(shape, 0, used.chain),
        status(shape, kNotConverged),
        within_validity(shape, false, used.prbm || used.bcm),
        converged(shape, false),
        method(count, workers),
        method_reason(count, workers),
        branch(count, workers),
        family(count, workers),
        message(count, workers),
        termination(count, workers),
        stability(count, workers),
        stability_message(count, workers),
        stable_search(count, workers),
        warnings(count, workers),
        validity_source(used.prbm ? count : 0, workers),
        constants(used.prbm3r ? count : 0, workers),
        special_points(count, workers) {}
  NumpyColumn<double> n, alpha2, mu, a_over_l, b_over_l, theta0, root_moment, target_residual,
      first_limit_load_factor, reaction_Fx, reaction_Fy, reaction_M, stability_index,
      stability_margin, Theta, theta_max, expected_error, expected_error_per_length,
      max_element_deflection, slenderness, axial_stiffness_d;
  // stability_index is a float column: NaN where not judged, the scalar call's None.
  NumpyColumn<long long> iterations, inflection_points, limit_points, elements, increments, status;
  NumpyColumn<bool> within_validity, converged;
  // warnings: the point's warnings joined by newlines (returned as a list per point).
  TextColumn method, method_reason, branch, family, message, termination, stability,
      stability_message, stable_search, warnings, validity_source, constants;
  // special_points: the JSON text of the key (beam_keys::special_points), "" for null.
  TextColumn special_points;
  std::atomic<bool> any_prbm{false}, any_chain{false}, any_prbm3r{false}, any_bcm{false};
};

double finite_or_nan(double v) { return std::isfinite(v) ? v : kNaN; }

void fail_point(Columns& c, std::size_t i, int worker, int status, std::string_view message) {
  c.status.data[i] = status;
  c.message.set(i, worker, message);
  c.termination.set(i,
                    worker,
                    termination_name(status == kInvalid ? Termination::kInvalidInput
                                                        : Termination::kNoConvergence));
}

// One load: the checks and keys of `flexure beam --json` (cli/beam_command.cpp).
void solve_one(const BeamInput& base,
               const char* given_flag,
               double n,
               double mu,
               double value,
               Columns& c,
               std::size_t i,
               int worker) {
  c.n.data[i] = n;
  c.mu.data[i] = mu;
  // A text column reads another point's text where it was never set: a failed load's are set
  // here.
  c.stability.set(i, worker, stability_name(StabilityKind::kNotChecked));
  c.stability_message.set(i, worker, "");
  c.stable_search.set(i, worker, "");
  c.warnings.set(i, worker, "");
  c.special_points.set(i, worker, "");
  try {
    cli::require_finite_input(n, "--n (load ratio n)");
    cli::require_finite_input(mu, "--mu (end moment M l/EI)");
    BeamProblem problem = base.problem;
    problem.load_ratio_n = n;
    problem.mu = mu;
    if (problem.given == BeamProblem::Given::kBOverL) {
      cli::require_in_range(value, "--b-over-l (tip deflection b/l)", -1.0, 1.0);
    } else {
      cli::require_finite_input(value, given_flag);
    }
    problem.value = value;
    const BeamSolution s = solve_beam(base.method, problem);
    c.method.set(i, worker, to_string(s.method));
    c.method_reason.set(i, worker, s.method_reason);
    c.expected_error.data[i] = finite_or_nan(s.expected_error);
    c.expected_error_per_length.data[i] = finite_or_nan(s.expected_error_per_length);
    c.iterations.data[i] = s.iterations;
    if (!s.converged() || !std::isfinite(s.alpha2) || !std::isfinite(s.tip.a_over_l) ||
        !std::isfinite(s.tip.b_over_l) || !std::isfinite(s.tip.theta0)) {
      fail_point(
          c, i, worker, kNotConverged, s.message.empty() ? "no converged solution" : s.message);
      c.termination.set(i, worker, termination_name(s.termination));
      return;
    }
    c.status.data[i] = kConverged;
    c.converged.data[i] = true;
    c.termination.set(i, worker, termination_name(s.termination));
    c.message.set(i, worker, s.message);
    c.n.data[i] = finite_or_nan(s.load_ratio_n);
    c.alpha2.data[i] = s.alpha2;
    c.mu.data[i] = finite_or_nan(s.mu);
    c.a_over_l.data[i] = s.tip.a_over_l;
    c.b_over_l.data[i] = s.tip.b_over_l;
    c.theta0.data[i] = s.tip.theta0;
    c.branch.set(i, worker, s.branch);
    c.inflection_points.data[i] = s.inflection_points;
    c.root_moment.data[i] = finite_or_nan(s.root_moment);
    c.limit_points.data[i] = s.limit_points;
    c.target_residual.data[i] = finite_or_nan(s.target_residual);
    if (s.limit_points > 0) c.first_limit_load_factor.data[i] = s.first_limit_load_factor;
    c.family.set(i, worker, s.family);
    c.reaction_Fx.data[i] = finite_or_nan(s.reactions.Fx);
    c.reaction_Fy.data[i] = finite_or_nan(s.reactions.Fy);
    c.reaction_M.data[i] = finite_or_nan(s.reactions.M);
    if (s.special_points_known) {
      c.special_points.set(i, worker, beam_keys::special_points<Json>(problem, s).dump());
    }
    c.stability.set(i, worker, stability_name(s.stability.kind));
    c.stability_message.set(i, worker, s.stability.message);
    c.stable_search.set(i, worker, s.stable_search);
    std::string joined;
    for (const std::string& w : cli::beam_warnings(problem, s))
      joined += (joined.empty() ? "" : "\n") + w;
    c.warnings.set(i, worker, joined);
    if (s.stability.judged()) {
      c.stability_index.data[i] = s.stability.index;
      c.stability_margin.data[i] = finite_or_nan(s.stability.margin);
    }
    if (s.method == BeamMethod::kPrbm) {
      c.any_prbm = true;
      c.within_validity.data[i] = s.prbm_inside_validity;
      c.Theta.data[i] = s.prbm_Theta;
      c.theta_max.data[i] = s.prbm_theta_max;
      c.validity_source.set(i, worker, s.prbm_limits_source);
    }
    if (s.method == BeamMethod::kChain) {
      c.any_chain = true;
      c.elements.data[i] = s.elements;
      c.increments.data[i] = s.increments;
    }
    if (s.method == BeamMethod::kPrbm3r) {
      c.any_prbm3r = true;
      c.constants.set(i, worker, s.model_constants);
    }
    if (s.method == BeamMethod::kBcm || s.method == BeamMethod::kCbcm) {
      c.any_bcm = true;
      c.elements.data[i] = s.elements;
      c.max_element_deflection.data[i] = s.max_element_deflection;
      c.within_validity.data[i] = s.model_inside_validity;
      c.slenderness.data[i] = s.slenderness > 0.0 ? s.slenderness : kNaN;  // the tool's null
      c.axial_stiffness_d.data[i] =
          std::isfinite(s.axial_stiffness_d) ? s.axial_stiffness_d : kNaN;  // the tool's null
    }
  } catch (const InvalidInput& e) {
    fail_point(c, i, worker, kInvalid, e.what());
  } catch (const NoConvergence& e) {
    fail_point(c, i, worker, kNotConverged, e.what());
  } catch (const std::exception& e) {
    fail_point(c, i, worker, kNotConverged, std::string("error: ") + e.what());
  }
}

// The keywords of flexure.beam as the library's beam request (beam/beam_request.h), as
// python/flexure/_beam.py normalises them (numbers as float or int, names and angles as str,
// switches as bool); a keyword left out keeps the command's default, and a value given is one the
// checks see as given. Used by the scalar beam() and by beam_many().
BeamRequest request_from_keywords(const py::dict& kw) {
  static const char* const known[] = {
      "n",        "mu",         "alpha2",        "theta0",     "b_over_l",  "method",
      "boundary", "tip_x",      "tip_y",         "tip_angle",  "follower",  "shape",
      "elements", "increments", "chain_variant", "integrator", "stability", "stable",
      "tol",      "constants",  "slenderness"};
  for (const auto& item : kw) {
    const std::string key = py::str(item.first);
    if (std::find(std::begin(known), std::end(known), key) == std::end(known)) {
      throw py::type_error("beam: unexpected keyword '" + key + "'");
    }
  }
  auto get = [&](const char* key) -> py::object {
    return kw.contains(key) ? py::reinterpret_borrow<py::object>(kw[key]) : py::object(py::none());
  };
  auto number = [&](const char* key) -> std::optional<double> {
    py::object v = get(key);
    if (v.is_none()) return std::nullopt;
    return v.cast<double>();
  };
  auto integer = [&](const char* key) -> std::optional<int> {
    py::object v = get(key);
    if (v.is_none()) return std::nullopt;
    return v.cast<int>();
  };
  auto text = [&](const char* key) -> std::optional<std::string> {
    py::object v = get(key);
    if (v.is_none()) return std::nullopt;
    return v.cast<std::string>();
  };
  BeamRequest r;
  r.load_ratio_n = number("n").value_or(0.0);
  r.mu = number("mu").value_or(0.0);
  r.alpha2 = number("alpha2");
  r.theta0 = text("theta0");
  r.b_over_l = number("b_over_l");
  if (auto v = text("method")) r.method = std::move(*v);
  if (auto v = text("boundary")) r.boundary = std::move(*v);
  r.tip_x = number("tip_x");
  r.tip_y = number("tip_y");
  r.tip_angle = text("tip_angle");
  r.follower = number("follower").value_or(0.0);
  r.shape_points = integer("shape");
  r.elements = integer("elements");
  r.increments = integer("increments").value_or(1);
  if (auto v = text("chain_variant")) r.chain_variant = std::move(*v);
  r.integrator = text("integrator");
  const std::optional<std::string> stability = text("stability");
  r.judge_stability = !stability || same_name(*stability, "on");
  r.stable = !get("stable").is_none() && get("stable").cast<bool>();
  r.tolerance = number("tol");
  r.constants = text("constants");
  r.slenderness = number("slenderness");
  return r;
}

// beam_many(keywords, n, mu, value, shape, threads): flexure.beam's keywords validated once (the
// given quantity and every option), then solved at each (n[i], mu[i], value[i]) (flat float64
// arrays of one length; `value` is the given alpha2, theta0 or b/l) on `threads` threads without
// the lock on the interpreter; the columns of `flexure beam --json` shaped `shape`, plus `status`.
py::dict beam_many(const py::dict& keywords,
                   const py::array_t<double, py::array::c_style | py::array::forcecast>& n,
                   const py::array_t<double, py::array::c_style | py::array::forcecast>& mu,
                   const py::array_t<double, py::array::c_style | py::array::forcecast>& value,
                   const std::vector<py::ssize_t>& shape,
                   int threads) {
  const std::size_t count = static_cast<std::size_t>(n.size());
  if (static_cast<std::size_t>(mu.size()) != count ||
      static_cast<std::size_t>(value.size()) != count) {
    throw std::invalid_argument("beam_many: n, mu and value must have one length");
  }
  // Checked once, with a valid placeholder for the given load, by the library with the tool's
  // names (so the tool's messages); a physical beam or a chain file never gets here
  // (python/flexure/_beam.py refuses them for arrays).
  const BeamRequest request = request_from_keywords(keywords);
  BeamInput base;
  {
    py::gil_scoped_release release;
    base = make_beam_input(request, BeamRequestNames::command_line());
  }
  if (base.problem.shape_points > 0) {
    throw InvalidInput("shape= returns one curve per load: give scalar loads with shape=");
  }
  const char* given_flag = base.problem.given == BeamProblem::Given::kTheta0
                               ? "--theta0 (tip angle)"
                               : "--alpha2 (P l^2/EI)";
  const int workers =
      static_cast<int>(std::clamp<std::size_t>(count / 256 + 1, 1, std::max(threads, 1)));
  // Auto may resolve to any method, so it keeps every column.
  const bool auto_method = base.method == BeamMethod::kAuto;
  UsedKeys used;
  used.prbm = auto_method || base.method == BeamMethod::kPrbm;
  used.chain = auto_method || base.method == BeamMethod::kChain;
  used.prbm3r = auto_method || base.method == BeamMethod::kPrbm3r;
  used.bcm = auto_method || base.method == BeamMethod::kBcm || base.method == BeamMethod::kCbcm;
  Columns c(shape, count, workers, used);
  const double* pn = n.data();
  const double* pmu = mu.data();
  const double* pv = value.data();
  // Ctrl-C between the calling thread's chunks (at most every 50 ms, python/object_support.h):
  // the other workers stop at their next chunk and are joined before KeyboardInterrupt is raised.
  ProgressBridge interrupt{py::none()};
  {
    py::gil_scoped_release release;
    std::atomic<std::size_t> next{0}, solved{0};
    std::atomic<bool> stopped{false};
    constexpr std::size_t kChunk = 256;
    auto work = [&](int worker) {
      while (!stopped.load(std::memory_order_relaxed)) {
        const std::size_t start = next.fetch_add(kChunk);
        if (start >= count) return;
        const std::size_t stop = std::min(count, start + kChunk);
        for (std::size_t i = start; i < stop; ++i) {
          solve_one(base, given_flag, pn[i], pmu[i], pv[i], c, i, worker);
        }
        solved += stop - start;
        if (worker != 0) continue;
        try {
          interrupt(solved.load(), count);
        } catch (const ProgressBridge::Stopped&) {
          stopped = true;
        }
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < workers; ++t) pool.emplace_back(work, t);
    work(0);
    for (std::thread& t : pool) t.join();
  }
  interrupt.raise_if_stopped();
  py::dict out;
  out["method"] = c.method.to_numpy(shape);
  out["method_reason"] = c.method_reason.to_numpy(shape);
  out["expected_error"] = c.expected_error.array;
  out["expected_error_per_length"] = c.expected_error_per_length.array;
  out["n"] = c.n.array;
  out["alpha2"] = c.alpha2.array;
  out["mu"] = c.mu.array;
  out["a_over_l"] = c.a_over_l.array;
  out["b_over_l"] = c.b_over_l.array;
  out["theta0"] = c.theta0.array;
  out["iterations"] = c.iterations.array;
  out["converged"] = c.converged.array;
  out["branch"] = c.branch.to_numpy(shape);
  out["inflection_points"] = c.inflection_points.array;
  out["root_moment"] = c.root_moment.array;
  out["limit_points"] = c.limit_points.array;
  out["target_residual"] = c.target_residual.array;
  out["first_limit_load_factor"] = c.first_limit_load_factor.array;
  out["special_points"] = c.special_points.to_numpy_json(shape);
  out["family"] = c.family.to_numpy(shape);
  out["message"] = c.message.to_numpy(shape);
  out["termination"] = c.termination.to_numpy(shape);
  py::array boundary = py::module_::import("numpy").attr("full")(
      shape, py::str(std::string(to_string(base.problem.boundary))), py::dtype("O"));
  out["boundary"] = boundary;
  py::dict reactions;
  reactions["Fx"] = c.reaction_Fx.array;
  reactions["Fy"] = c.reaction_Fy.array;
  reactions["M"] = c.reaction_M.array;
  out["reactions"] = reactions;
  // In the tool's order for each method (a key two methods share keeps its first place).
  out["stability"] = c.stability.to_numpy(shape);
  out["stability_index"] = c.stability_index.array;
  out["stability_margin"] = c.stability_margin.array;
  out["stability_message"] = c.stability_message.to_numpy(shape);
  out["stable_search"] = base.problem.stable ? c.stable_search.to_numpy(shape)
                                             : py::module_::import("numpy").attr("full")(
                                                   shape, py::none(), py::dtype("O"));
  if (c.any_prbm) {
    out["within_validity"] = c.within_validity.array;
    out["Theta"] = c.Theta.array;
    out["theta_max"] = c.theta_max.array;
    out["validity_source"] = c.validity_source.to_numpy(shape);
  }
  if (c.any_chain) {
    out["elements"] = c.elements.array;
    out["increments"] = c.increments.array;
  }
  if (c.any_prbm3r) out["constants"] = c.constants.to_numpy(shape);
  if (c.any_bcm) {
    out["elements"] = c.elements.array;
    out["max_element_deflection"] = c.max_element_deflection.array;
    out["within_validity"] = c.within_validity.array;
    out["slenderness"] = c.slenderness.array;
    out["axial_stiffness_d"] = c.axial_stiffness_d.array;
  }
  out["warnings"] = c.warnings.to_numpy_lists(shape);
  out["status"] = c.status.array;
  return out;
}

}  // namespace
}  // namespace flexure::python

PYBIND11_MODULE(_core, m) {
  flexure::disable_gsl_abort();
  m.doc() = "flexure's compiled core; use the functions of the flexure package (docs/python.md)";
  m.attr("version") = flexure::kVersion;
  m.attr("git_commit") = flexure::kGitCommit;
  m.def("run",
        &flexure::python::run,
        py::arg("args"),
        py::kw_only(),
        py::arg("progress") = py::none(),
        "Runs one flexure command (the tool's arguments, without 'flexure') in this process: "
        "(kind, payload, warnings, exit_code). `progress(done, total)` is called at each step of "
        "the commands whose long work can be stopped (dynamics, design cfm --model exact, design "
        "mechanism, "
        "mechanism analyze's exact stroke, cfm --table --exact, sweep beam); Ctrl-C (or an "
        "exception from the callable) stops them at the next step.");
  m.def("toml_text",
        &flexure::python::toml_text,
        py::arg("json_text"),
        "The TOML document of a dict given as JSON text (a mechanism design passed as a dict).");
  m.def("beam_many",
        &flexure::python::beam_many,
        py::arg("keywords"),
        py::arg("n"),
        py::arg("mu"),
        py::arg("value"),
        py::arg("shape"),
        py::arg("threads"),
        "flexure beam at many loads (flat float64 arrays) on worker threads.");
  m.def(
      "beam",
      [](const py::kwargs& keywords) {
        return flexure::python::beam_request(flexure::python::request_from_keywords(keywords));
      },
      "flexure beam --json for keyword values (no command line): (kind, payload, warnings, "
      "exit_code) as run().");
  flexure::python::bind_objects(m);
}
