// impact.sweep(): `impact sweep` from Python, by the command's own engine
// (src/cli/sweep_runner.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace impact::python {

void add_sweep(pybind11::module_& m);

}  // namespace impact::python
