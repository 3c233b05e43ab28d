// A vector's storage handed to NumPy as it is, without a copy: the array owns it through a capsule.
#pragma once

#include <pybind11/numpy.h>

#include <vector>

namespace impact::python {

template <class T>
pybind11::array_t<T> give(std::vector<T>&& values) {
  auto* owned = new std::vector<T>(std::move(values));
  pybind11::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return pybind11::array_t<T>(static_cast<pybind11::ssize_t>(owned->size()), owned->data(), owner);
}

}  // namespace impact::python
