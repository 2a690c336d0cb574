// Constraints written in Python: Model.add_constraint(...) turns callables
// f, df/du, d2f/du2 over the x, y displacements of named nodes into an
// ExternalConstraint, which the analysis enforces with the same constraint
// element as the deck's constraints.

#include <pybind11/stl.h>

#include <cstdio>

#include "bindings.hpp"
#include "tether/model/model.hpp"

namespace tether::python {

namespace {

/// `t` as `{:g}` formats it.
std::string fmt_time(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", t);
  return buffer;
}

/// Calls the Python callables, with the GIL, and checks their shapes.
class PythonConstraint final : public ExternalConstraint {
 public:
  /// `with_time`: the callables take the total time as a third argument.
  PythonConstraint(std::string name, py::object f, py::object gradient, py::object hessian, int m, bool with_time)
      : name_(std::move(name)),
        f_(std::move(f)),
        gradient_(std::move(gradient)),
        hessian_(std::move(hessian)),
        m_(m),
        with_time_(with_time) {}
  PythonConstraint(const PythonConstraint&) = delete;
  PythonConstraint& operator=(const PythonConstraint&) = delete;
  ~PythonConstraint() override {
    // The last owner may be a model copy dropped while the analysis runs without the GIL.
    py::gil_scoped_acquire gil;
    f_ = py::object(), gradient_ = py::object(), hessian_ = py::object();
  }

  int n_equations() const override { return m_; }

  void evaluate(const Eigen::VectorXd& u, const Eigen::VectorXd& reference, double, double total_time,
                Eigen::VectorXd& f, Eigen::MatrixXd& gradient, std::vector<Eigen::MatrixXd>* hessian) const override {
    py::gil_scoped_acquire gil;
    const auto n = static_cast<py::ssize_t>(u.size());
    py::array_t<double> u_py(n, u.data()), x_py(n, reference.data());
    const auto call = [&](const py::object& function, const char* what) {
      try {
        return with_time_ ? function(u_py, x_py, total_time) : function(u_py, x_py);
      } catch (py::error_already_set& e) {
        throw CallbackError(std::move(e), std::string("raised by ") + what + " of constraint " + name_ +
                                              " at total time " + fmt_time(total_time));
      }
    };
    copy(call(f_, "f"), {m_}, f.data(), "f");
    // Row-major (m, n) from Python into the column-major gradient.
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> g(m_, n);
    copy(call(gradient_, "the gradient"), {m_, n}, g.data(), "gradient");
    gradient = g;
    if (!hessian || hessian_.is_none()) return;
    std::vector<double> h(static_cast<std::size_t>(m_ * n * n));
    copy(call(hessian_, "the hessian"), {m_, n, n}, h.data(), "hessian");
    for (py::ssize_t k = 0; k < m_; ++k)
      (*hessian)[static_cast<std::size_t>(k)] =
          Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(h.data() + k * n * n, n, n);
  }

 private:
  /// Copies `value` (shape `shape`, or without its leading 1 when m = 1) into `out`.
  void copy(const py::object& value, std::vector<py::ssize_t> shape, double* out, const char* what) const {
    auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
    if (!a) throw py::type_error("constraint " + name_ + ": " + what + " must return numbers (an array)");
    std::vector<py::ssize_t> got(a.shape(), a.shape() + a.ndim());
    std::vector<py::ssize_t> squeezed(shape.begin() + 1, shape.end());
    if (got != shape && !(m_ == 1 && got == squeezed)) {
      std::string expected, actual;
      for (auto s : shape) expected += (expected.empty() ? "" : ", ") + std::to_string(s);
      for (auto s : got) actual += (actual.empty() ? "" : ", ") + std::to_string(s);
      throw py::value_error("constraint " + name_ + ": " + what + " returned shape (" + actual + "), expected (" +
                            expected + ")");
    }
    std::copy(a.data(), a.data() + a.size(), out);
  }

  std::string name_;
  py::object f_, gradient_, hessian_;
  py::ssize_t m_;
  bool with_time_;
};

Enforcement enforcement(const std::string& method, double epsilon, double penalty, double tolerance, int max_updates) {
  Enforcement e;
  if (method == "lagrange") e.method = Enforcement::Method::Lagrange;
  else if (method == "penalty") e.method = Enforcement::Method::Penalty;
  else if (method == "augmented") e.method = Enforcement::Method::Augmented;
  else throw py::value_error("enforcement must be 'lagrange', 'penalty' or 'augmented', not '" + method + "'");
  if (epsilon < 0) throw py::value_error("epsilon must be >= 0");
  if (e.method != Enforcement::Method::Lagrange && !(penalty > 0))
    throw py::value_error("the " + method + " enforcement needs penalty > 0");
  if (tolerance < 0) throw py::value_error("tolerance must be >= 0");
  if (max_updates <= 0) throw py::value_error("max_updates must be > 0");
  e.epsilon = epsilon, e.penalty = penalty, e.tolerance = tolerance, e.max_updates = max_updates;
  return e;
}

void add_constraint(Model& model, const std::string& name, const std::vector<int>& labels, const py::object& f,
                    const py::object& gradient, const py::object& hessian, const std::string& method, double epsilon,
                    double penalty, double tolerance, int max_updates, bool with_time) {
  if (labels.empty()) throw py::value_error("constraint " + name + ": no nodes");
  ConstraintData c;
  c.kind = ConstraintData::Kind::External;
  c.name = name;
  for (int label : labels) {
    const auto it = model.node_index.find(label);
    if (it == model.node_index.end()) throw py::key_error("constraint " + name + ": no node " + std::to_string(label));
    c.nodes.push_back(it->second);
  }
  c.enforcement = enforcement(method, epsilon, penalty, tolerance, max_updates);
  c.where = SourceLocation{"<python>", 0};
  // The number of equations: the length of f at the reference state.
  const auto n = static_cast<py::ssize_t>(2 * labels.size());
  py::array_t<double> zero(n), reference(n);
  for (py::ssize_t k = 0; k < n; ++k) {
    zero.mutable_at(k) = 0;
    reference.mutable_at(k) = model.coords[static_cast<std::size_t>(c.nodes[static_cast<std::size_t>(k / 2)])][k % 2];
  }
  const auto f0 = py::array_t<double, py::array::forcecast>::ensure(with_time ? f(zero, reference, 0.0)
                                                                             : f(zero, reference));
  if (!f0 || f0.ndim() > 1 || f0.size() == 0) throw py::value_error("constraint " + name + ": f must return a number or a 1-D array");
  c.external = std::make_shared<PythonConstraint>(name, f, gradient, hessian, static_cast<int>(f0.size()), with_time);
  model.constraints.push_back(std::move(c));
}

}  // namespace

void bind_constraints(py::module_& m) {
  auto model = py::reinterpret_borrow<py::class_<Model, std::shared_ptr<Model>>>(m.attr("Model"));
  model.def("add_constraint", &add_constraint, py::arg("name"), py::arg("nodes"), py::arg("f"), py::arg("gradient"),
            py::arg("hessian") = py::none(), py::arg("enforcement") = "lagrange", py::arg("epsilon") = 0.0,
            py::arg("penalty") = 0.0, py::arg("tolerance") = 0.0, py::arg("max_updates") = 100,
            py::arg("time") = false,
            "Adds the constraint f(u, X) = 0 written in Python (see docs/python.md).");
  model.def(
      "remove_constraint",
      [](Model& md, const std::string& name) {
        const auto it = std::find_if(md.constraints.begin(), md.constraints.end(),
                                     [&](const ConstraintData& c) { return c.name == name; });
        if (it == md.constraints.end()) throw py::key_error("no constraint " + name);
        md.constraints.erase(it);
      },
      py::arg("name"), "Removes the (first) constraint of that name.");
}

}  // namespace tether::python
