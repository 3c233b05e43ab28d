// The module's NumPy arrays: a vector's storage handed over without a copy, or an array of zeros
// to be filled. No array the module returns holds memory it did not write.
#pragma once

#include <pybind11/numpy.h>

#include <algorithm>
#include <vector>

namespace impact::python {

template <class T>
pybind11::array_t<T> give(std::vector<T>&& values) {
  auto* owned = new std::vector<T>(std::move(values));
  pybind11::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return pybind11::array_t<T>(static_cast<pybind11::ssize_t>(owned->size()), owned->data(), owner);
}

// n zeros, made with the GIL, to be filled in place while a run steps without it.
template <class T>
pybind11::array_t<T> zeros(pybind11::ssize_t n) {
  pybind11::array_t<T> array(n);
  std::fill_n(array.mutable_data(), n, T{});
  return array;
}

}  // namespace impact::python
