#pragma once
// flexure._core's classes over the library's types (python/objects.cpp).
#include <pybind11/pybind11.h>

namespace flexure::python {

void bind_objects(pybind11::module_& m);

}  // namespace flexure::python
