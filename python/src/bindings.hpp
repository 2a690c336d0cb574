#pragma once
// The pieces of the `tether._tether` extension module, one per C++ area
// (model, results, job, constraints), mirroring the library's folders.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace tether {
struct DeckWarning;
struct Model;
}

namespace tether::python {

namespace py = pybind11;

/// [(file, line, message), ...] of the reader's warnings.
py::list warning_list(const std::vector<DeckWarning>& warnings);

/// A Python exception raised in a callback the analysis made (the progress
/// callable, a Python constraint), carried through the C++ run: what() is the
/// exception's first line and `where` (for the job's verdict in the `.sta`);
/// Job.run hands `error` itself back to Python, with `where` as a note.
/// Construct and destroy it with the GIL held (it is caught with the GIL).
struct CallbackError : std::runtime_error {
  CallbackError(py::error_already_set error_, const std::string& where_)
      : std::runtime_error(summary(error_) + " (" + where_ + ")"), error(std::move(error_)), where(where_) {}
  py::error_already_set error;
  std::string where;

  /// "Type: message" of the exception, its first line ("Type" alone without a message).
  static std::string summary(const py::error_already_set& e) {
    std::string line(e.what());
    line = line.substr(0, line.find('\n'));
    const std::string empty = ": <EMPTY MESSAGE>";  // pybind11's text for an exception without arguments
    if (line.size() >= empty.size() && line.compare(line.size() - empty.size(), empty.size(), empty) == 0)
      line.resize(line.size() - empty.size());
    return line;
  }
};

void bind_errors(py::module_& m);
void bind_model(py::module_& m);
void bind_results(py::module_& m);
void bind_job(py::module_& m);
void bind_constraints(py::module_& m);
/// Mesh and section editing methods of tether.Model (mesh_bindings.cpp).
void bind_mesh_editing(py::module_& m, py::class_<Model, std::shared_ptr<Model>>& model);

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
