#pragma once
// The pieces of the `tether._tether` extension module, one per C++ area
// (model, results, job, constraints), mirroring the library's folders.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace tether {
struct DeckWarning;
}

namespace tether::python {

namespace py = pybind11;

/// [(file, line, message), ...] of the reader's warnings.
py::list warning_list(const std::vector<DeckWarning>& warnings);

void bind_errors(py::module_& m);
void bind_model(py::module_& m);
void bind_results(py::module_& m);
void bind_job(py::module_& m);
void bind_constraints(py::module_& m);

/// A new (n, k) float64 array filled by `value(i, j)`.
template <class F>
py::array_t<double> matrix(std::size_t n, std::size_t k, F value) {
  py::array_t<double> a({n, k});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < k; ++j) v(i, j) = value(i, j);
  return a;
}

/// A new (n,) array of `T` filled by `value(i)`.
template <class T, class F>
py::array_t<T> vector(std::size_t n, F value) {
  py::array_t<T> a(n);
  auto v = a.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < n; ++i) v(i) = value(i);
  return a;
}

}  // namespace tether::python
