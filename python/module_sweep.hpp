// impact.sweep(): `impact sweep` from Python, by the same engine (impact::sweep(),
// src/scene/sweep_engine.hpp), its columns as NumPy arrays.
#pragma once

#include <pybind11/pybind11.h>

namespace impact::python {

void add_sweep(pybind11::module_& m);

}  // namespace impact::python
