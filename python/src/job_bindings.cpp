// tether.Job: runs a model through the C++ Job (the same one `tether run`
// uses), with an optional progress callback, and hands out its increments.

#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "tether/job/job.hpp"
#include "tether/solvers/linear_solver.hpp"

namespace tether::python {

namespace {

/// The Python object behind tether.Job: the C++ Job over a model shared with
/// Python, and the increments of the last run.
struct PyJob {
  std::shared_ptr<Model> model;
  std::unique_ptr<Job> job;
  std::vector<std::shared_ptr<JobIncrement>> results;
};

/// The run's link to Python (holding the GIL only while it calls in): after
/// every Newton iteration it lets Python handle pending signals, so that
/// Ctrl-C (KeyboardInterrupt) stops a long run within an iteration; after
/// every attempt it calls the progress callable, when there is one.
class PythonObserver final : public AnalysisObserver {
 public:
  explicit PythonObserver(std::optional<py::function> progress) : progress_(std::move(progress)) {}
  PythonObserver(const PythonObserver&) = delete;
  PythonObserver& operator=(const PythonObserver&) = delete;
  ~PythonObserver() override {
    py::gil_scoped_acquire gil;
    progress_.reset();
  }
  void on_iteration(int, const IterationNorms&) override {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw CallbackError(py::error_already_set(), "a signal arrived during the run");
  }
  void on_increment(const IncrementReport& r) override {
    if (!progress_) return;
    py::gil_scoped_acquire gil;
    try {
      (*progress_)(r);
    } catch (py::error_already_set& e) {
      throw CallbackError(std::move(e), "raised by the progress callback after step " + std::to_string(r.step) +
                                            " increment " + std::to_string(r.increment) + " attempt " +
                                            std::to_string(r.attempt));
    }
  }

 private:
  std::optional<py::function> progress_;
};

JobOptions::Keep parse_keep(const std::string& keep) {
  if (keep == "all") return JobOptions::Keep::All;
  if (keep == "last") return JobOptions::Keep::Last;
  if (keep == "none") return JobOptions::Keep::None;
  throw py::value_error("keep must be 'all', 'last' or 'none', not '" + keep + "'");
}

std::unique_ptr<PyJob> make_job(std::shared_ptr<Model> model, std::optional<std::filesystem::path> output_dir,
                                std::optional<std::string> name, const std::string& solver, const std::string& keep) {
  JobOptions options;
  try {
    options.analysis.solver = parse_solver_kind(solver);
  } catch (const std::exception& e) {
    throw py::value_error(e.what());
  }
  if (output_dir) options.output_dir = *output_dir;
  if (name) options.name = *name;
  options.keep = parse_keep(keep);
  auto job = std::make_unique<PyJob>();
  job->model = model;
  job->job = std::make_unique<Job>(std::move(model), std::move(options));
  return job;
}

JobSummary run(PyJob& self, const std::optional<py::function>& progress, bool check) {
  PythonObserver observer(progress);
  self.results.clear();
  const auto take_results = [&] {
    for (JobIncrement& inc : self.job->take_results())
      self.results.push_back(std::make_shared<JobIncrement>(std::move(inc)));
  };
  JobSummary summary;
  try {
    py::gil_scoped_release release;
    summary = self.job->run(&observer);
  } catch (CallbackError& e) {
    take_results();  // what converged before the callback raised
    // The callback's own exception goes back to Python, noting where it was raised.
    if (py::hasattr(e.error.value(), "add_note")) e.error.value().attr("add_note")(e.where + "; the run stopped");
    throw e.error;
  } catch (...) {
    take_results();  // what converged before the error or the interruption
    throw;
  }
  take_results();
  if (check && !summary.completed) throw SolverError(summary.message);
  return summary;
}

void bind_reports(py::module_& m) {
  py::class_<IncrementReport>(m, "IncrementReport", "One attempt of an increment, as the progress callback gets it.")
      .def_readonly("step", &IncrementReport::step)
      .def_readonly("increment", &IncrementReport::increment)
      .def_readonly("attempt", &IncrementReport::attempt, "1 = first try, > 1 after cut-backs")
      .def_readonly("iterations", &IncrementReport::iterations)
      .def_readonly("step_time", &IncrementReport::step_time)
      .def_readonly("time", &IncrementReport::total_time)
      .def_readonly("increment_size", &IncrementReport::increment_size)
      .def_readonly("residual", &IncrementReport::residual)
      .def_readonly("converged", &IncrementReport::converged)
      .def("__repr__", [](const IncrementReport& r) {
        return "<tether.IncrementReport step " + std::to_string(r.step) + " increment " + std::to_string(r.increment) +
               " attempt " + std::to_string(r.attempt) + (r.converged ? " converged>" : " not converged>");
      });
  py::class_<JobSummary>(m, "Summary", "How a run went.")
      .def_readonly("completed", &JobSummary::completed, "every step reached its end")
      .def_readonly("message", &JobSummary::message, "'analysis complete' or why it stopped")
      .def_readonly("steps", &JobSummary::steps)
      .def_readonly("increments", &JobSummary::increments)
      .def_readonly("iterations", &JobSummary::iterations)
      .def_readonly("cutbacks", &JobSummary::cutbacks)
      .def_readonly("seconds", &JobSummary::seconds)
      .def("__bool__", [](const JobSummary& s) { return s.completed; })
      .def("__repr__", [](const JobSummary& s) {
        return "<tether.Summary " + s.message + ": " + std::to_string(s.increments) + " increments, " +
               std::to_string(s.iterations) + " iterations>";
      });
}

}  // namespace

void bind_job(py::module_& m) {
  bind_reports(m);
  py::class_<PyJob>(m, "Job", "Runs a model (see docs/python.md).")
      .def(py::init(&make_job), py::arg("model"), py::arg("output_dir") = py::none(), py::arg("name") = py::none(),
           py::arg("solver") = "auto", py::arg("keep") = "all")
      .def("run", &run, py::arg("progress") = py::none(), py::arg("check") = false)
      .def_property_readonly("model", [](const PyJob& j) { return j.model; })
      .def_property_readonly("results", [](const PyJob& j) { return j.results; })
      .def_property_readonly("name", [](const PyJob& j) { return j.job->name(); })
      .def_property_readonly("output_dir", [](const PyJob& j) -> std::optional<std::filesystem::path> {
        if (j.job->options().output_dir.empty()) return std::nullopt;
        return j.job->options().output_dir;
      })
      .def_property_readonly("written_files", [](const PyJob& j) { return j.job->written_files(); });
}

}  // namespace tether::python
