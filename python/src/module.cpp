// tether._tether: the compiled part of the `tether` Python package.

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "tether/core/error.hpp"
#include "tether/io/deck_reader.hpp"

namespace tether::python {

namespace {

/// The text of an InputError without its "file:line: error: " prefix.
std::string bare_message(const InputError& e) {
  const std::string what = e.what(), prefix = e.where().str() + ": error: ";
  return what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
}

/// Raises the Python exception `name` of tether._errors with `args`.
template <class... Args>
void raise(const char* name, Args&&... args) {
  py::object cls = py::module_::import("tether._errors").attr(name);
  py::object error = cls(std::forward<Args>(args)...);
  PyErr_SetObject(cls.ptr(), error.ptr());
}

}  // namespace

py::list warning_list(const std::vector<DeckWarning>& warnings) {
  py::list out;
  for (const DeckWarning& w : warnings) out.append(py::make_tuple(w.where.file, w.where.line, w.message));
  return out;
}

void bind_errors(py::module_&) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      raise("InputError", bare_message(e), e.where().file, e.where().line);
    } catch (const ModelError& e) {
      raise("ModelError", std::string(e.what()));
    } catch (const SolverError& e) {
      raise("SolverError", std::string(e.what()));
    } catch (const ResourceError& e) {
      raise("ResourceError", std::string(e.what()));
    }
  });
}

}  // namespace tether::python

PYBIND11_MODULE(_tether, m) {
  namespace py = pybind11;
  using namespace tether;
  m.doc() = "tether: nonlinear 2D finite elements with constraints and contact (compiled core)";
  m.attr("__version__") = TETHER_VERSION;
  python::bind_errors(m);
  python::bind_model(m);
  python::bind_results(m);
  python::bind_job(m);
  python::bind_constraints(m);

  m.def(
      "read_deck",
      [](const std::string& path) {
        std::vector<DeckWarning> warnings;
        auto model = std::make_shared<Model>(read_deck(path, &warnings));
        return py::make_tuple(model, python::warning_list(warnings));
      },
      py::arg("path"));
  m.def(
      "read_deck_string",
      [](const std::string& text, const std::string& name) {
        std::vector<DeckWarning> warnings;
        auto model = std::make_shared<Model>(read_deck_string(text, name, &warnings));
        return py::make_tuple(model, python::warning_list(warnings));
      },
      py::arg("text"), py::arg("name"));
}
