#pragma once
// What the module's object bindings share (python/objects.cpp, python/ladder_objects.cpp): the
// Python half's classes, a result's warnings as FlexureWarning, a solve without the interpreter
// lock, and the deflected-shape type.
#include <pybind11/pybind11.h>

#include <chrono>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure::python {

// The Python half's classes (python/flexure/_command.py), looked up when first needed: _core is
// imported by that module, so they do not exist yet when _core initialises.
inline pybind11::object module_class(const char* name) {
  return pybind11::module_::import("flexure._command").attr(name);
}

// A result's warnings as FlexureWarning, after the solve (the interpreter lock held).
inline void emit_warnings(const SolveStatus& status) {
  if (status.warnings.empty()) return;
  const pybind11::object category = module_class("FlexureWarning");
  for (const Warning& w : status.warnings) {
    if (PyErr_WarnEx(category.ptr(), w.text.c_str(), 2) != 0) throw pybind11::error_already_set();
  }
}

// Calls `solve` without the interpreter lock (other Python threads run during a long solve), then
// emits the result's warnings.
template <class Result, class Solve>
Result solve_released(Solve&& solve) {
  std::optional<Result> result;
  {
    pybind11::gil_scoped_release release;
    result.emplace(solve());
  }
  emit_warnings(*result);
  return std::move(*result);
}

// A long library call from Python with a progress callable (or None) and Ctrl-C (docs/python.md
// "Progress and Ctrl-C"). run() calls the library with the interpreter lock released; the
// library's progress hook calls operator(), which takes the lock, calls the callable (every step;
// without one, it only looks for a signal, at most every 50 ms), then runs Python's signal
// handlers (PyErr_CheckSignals: Ctrl-C raises KeyboardInterrupt there). An exception from either
// is kept and the step throws Stopped through the library, whose state is RAII. Every later step
// throws again (library code that caught the first does not keep going), and run() raises the
// kept exception whatever the call did after it.
class ProgressBridge {
 public:
  struct Stopped {};  // not a std::exception: no library handler of those swallows it

  explicit ProgressBridge(pybind11::object callable) : callable_(std::move(callable)) {}

  void operator()(std::size_t done, std::size_t total) {
    if (stopped_) throw Stopped{};
    const bool has_callable = !callable_.is_none();
    const auto now = std::chrono::steady_clock::now();
    if (!has_callable && now - last_check_ < std::chrono::milliseconds(50)) return;
    last_check_ = now;
    pybind11::gil_scoped_acquire gil;
    try {
      if (has_callable) callable_(done, total);
      if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
    } catch (pybind11::error_already_set& e) {
      e.restore();
      PyObject *type = nullptr, *value = nullptr, *trace = nullptr;
      PyErr_Fetch(&type, &value, &trace);
      type_ = pybind11::reinterpret_steal<pybind11::object>(type);
      value_ = pybind11::reinterpret_steal<pybind11::object>(value);
      trace_ = pybind11::reinterpret_steal<pybind11::object>(trace);
      stopped_ = true;
      throw Stopped{};
    }
  }

  template <class Result, class Call>
  Result run(Call&& call) {
    std::optional<Result> result;
    try {
      pybind11::gil_scoped_release release;
      result.emplace(call());
    } catch (...) {
      if (!stopped_) throw;
    }
    raise_if_stopped();
    // A result that is a SolveStatus carries warnings (a design report does not).
    if constexpr (std::is_base_of_v<SolveStatus, Result>) emit_warnings(*result);
    return std::move(*result);
  }

  // Raises the kept exception, if a step stopped the call (the interpreter lock held).
  void raise_if_stopped() {
    if (!stopped_) return;
    PyErr_Restore(type_.release().ptr(), value_.release().ptr(), trace_.release().ptr());
    throw pybind11::error_already_set();
  }

 private:
  pybind11::object callable_;
  pybind11::object type_, value_, trace_;
  bool stopped_ = false;
  std::chrono::steady_clock::time_point last_check_{};
};

// A deflected shape: the columns s, x, y, theta as float64 arrays; numpy.asarray(shape) is the
// (N, 4) array of the same columns (bound in objects.cpp).
struct Shape {
  std::vector<ShapePoint> points;
};

// The cheaper models of the ladder (python/ladder_objects.cpp).
void bind_ladder_objects(pybind11::module_& m);
// General planar mechanisms (python/mechanism_objects.cpp).
void bind_mechanism_objects(pybind11::module_& m);
// The constant-force slider mechanisms of the catalogue (python/catalogue_objects.cpp).
void bind_catalogue_objects(pybind11::module_& m);
// The dimensional design of those mechanisms (python/design_objects.cpp).
void bind_design_objects(pybind11::module_& m);

}  // namespace flexure::python
