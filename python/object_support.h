#pragma once
// What the module's object bindings share (python/objects.cpp, python/ladder_objects.cpp): the
// Python half's classes, a result's warnings as FlexureWarning, a solve without the interpreter
// lock, and the deflected-shape type.
#include <pybind11/pybind11.h>

#include <optional>
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

// A deflected shape: the columns s, x, y, theta as float64 arrays; numpy.asarray(shape) is the
// (N, 4) array of the same columns (bound in objects.cpp).
struct Shape {
  std::vector<ShapePoint> points;
};

// The cheaper models of the ladder (python/ladder_objects.cpp).
void bind_ladder_objects(pybind11::module_& m);
// General planar mechanisms (python/mechanism_objects.cpp).
void bind_mechanism_objects(pybind11::module_& m);

}  // namespace flexure::python
