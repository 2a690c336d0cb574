// tether.Increment: the owned results of one converged increment as NumPy
// arrays (node values without copies, read-only), constraint multipliers and
// contact state per slave node.

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "tether/job/job.hpp"

namespace tether::python {

namespace {

using IncrementPtr = std::shared_ptr<JobIncrement>;

/// A read-only (n, k) view of `n` consecutive fixed-size vectors of doubles
/// (Eigen::Vector2d, Tensor4) that keeps `owner` alive.
template <class V>
py::array_t<double> view(const std::vector<V>& values, std::size_t k, const py::object& owner) {
  static_assert(sizeof(V) % sizeof(double) == 0);
  py::array_t<double> a({values.size(), k}, {sizeof(V), sizeof(double)},
                        values.empty() ? nullptr : reinterpret_cast<const double*>(values.data()), owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

/// Every integration point, element by element: (label of the element, point
/// number 1.., values).
struct PointRows {
  std::vector<int> element, point;
  std::vector<const PointValues*> values;
};

PointRows point_rows(const JobIncrement& inc) {
  PointRows rows;
  for (std::size_t e = 0; e < inc.results.points.size(); ++e)
    for (std::size_t q = 0; q < inc.results.points[e].size(); ++q) {
      rows.element.push_back(inc.model->elements[e].id);
      rows.point.push_back(static_cast<int>(q) + 1);
      rows.values.push_back(&inc.results.points[e][q]);
    }
  return rows;
}

py::array_t<int> node_labels(const Model& model, const std::vector<int>& nodes) {
  return vector<int>(nodes.size(), [&](std::size_t i) { return model.node_ids[static_cast<std::size_t>(nodes[i])]; });
}

/// {name: value}; a name that repeats gets " (2)", " (3)", ...
void insert_unique(py::dict& d, const std::string& name, const py::object& value) {
  std::string key = name;
  for (int k = 2; d.contains(py::str(key)); ++k) key = name + " (" + std::to_string(k) + ")";
  d[py::str(key)] = value;
}

py::object multiplier_object(const Model& model, const MultiplierValues& v) {
  py::module_ types = py::module_::import("types");
  std::vector<int> nodes;
  for (const auto& f : v.nodal_force) nodes.push_back(f.node);
  py::list moments;
  for (const auto& f : v.nodal_force) moments.append(f.moment ? py::cast(*f.moment) : py::none());
  return types.attr("SimpleNamespace")(
      py::arg("name") = v.owner, py::arg("value") = py::array_t<double>(py::cast(v.value)),
      py::arg("constraint") = py::array_t<double>(py::cast(v.constraint)),
      py::arg("node_labels") = node_labels(model, v.nodes), py::arg("force_node_labels") = node_labels(model, nodes),
      py::arg("force") = matrix(v.nodal_force.size(), 2,
                                [&](std::size_t i, std::size_t j) { return v.nodal_force[i].force[static_cast<Eigen::Index>(j)]; }),
      py::arg("moment") = moments);
}

const char* status_name(ContactNodeValues::Status s) {
  switch (s) {
    case ContactNodeValues::Status::Open: return "open";
    case ContactNodeValues::Status::Stick: return "stick";
    case ContactNodeValues::Status::Slip: return "slip";
  }
  return "?";
}

py::object contact_object(const Model& model, const ContactPairValues& p) {
  const auto& n = p.nodes;
  auto column = [&](double ContactNodeValues::*field) {
    return vector<double>(n.size(), [&](std::size_t i) { return n[i].*field; });
  };
  std::vector<std::string> status;
  std::vector<int> nodes, master_element, master_face;
  for (const auto& c : n) {
    status.emplace_back(status_name(c.status)), nodes.push_back(c.node);
    master_element.push_back(c.master_element), master_face.push_back(c.master_face);
  }
  py::module_ types = py::module_::import("types");
  py::dict fields;
  fields["name"] = p.name;
  fields["node_labels"] = node_labels(model, nodes);
  fields["status"] = py::array(py::cast(status));
  fields["closed"] = vector<bool>(n.size(), [&](std::size_t i) { return n[i].status != ContactNodeValues::Status::Open; });
  fields["gap"] = column(&ContactNodeValues::gap);
  fields["pressure"] = column(&ContactNodeValues::pressure);
  fields["shear"] = column(&ContactNodeValues::shear);
  fields["normal_force"] = column(&ContactNodeValues::normal_force);
  fields["tangential_force"] = column(&ContactNodeValues::tangential_force);
  fields["slip"] = column(&ContactNodeValues::slip);
  fields["total_slip"] = column(&ContactNodeValues::total_slip);
  fields["dissipation"] = column(&ContactNodeValues::dissipation);
  fields["xi"] = column(&ContactNodeValues::xi);
  fields["master_element"] = py::array_t<int>(py::cast(master_element));
  fields["master_face"] = py::array_t<int>(py::cast(master_face));
  fields["force"] = matrix(n.size(), 2, [&](std::size_t i, std::size_t j) { return n[i].force[static_cast<Eigen::Index>(j)]; });
  fields["total_force"] = vector<double>(2, [&](std::size_t j) { return p.total_force[static_cast<Eigen::Index>(j)]; });
  fields["total_dissipation"] = p.dissipation;
  return types.attr("SimpleNamespace")(**fields);
}

/// meshio's name of an element shape (node order: ABAQUS = VTK = meshio).
const char* meshio_type(Shape shape) {
  switch (shape) {
    case Shape::Tri3: return "triangle";
    case Shape::Quad4: return "quad";
    case Shape::Tri6: return "triangle6";
    case Shape::Quad8: return "quad8";
  }
  return "?";
}

/// [(meshio type, (ne, k) node indices, (ne,) element indices)], one block
/// per run of elements of one shape, in the model's element order.
py::list cell_blocks(const Model& model) {
  py::list out;
  std::size_t e = 0;
  while (e < model.elements.size()) {
    const Shape shape = model.elements[e].type.shape;
    std::size_t end = e;
    while (end < model.elements.size() && model.elements[end].type.shape == shape) ++end;
    const std::size_t k = model.elements[e].nodes.size();
    py::array_t<long> cells({end - e, k});
    auto c = cells.mutable_unchecked<2>();
    for (std::size_t i = e; i < end; ++i)
      for (std::size_t a = 0; a < k; ++a) c(static_cast<py::ssize_t>(i - e), static_cast<py::ssize_t>(a)) = model.elements[i].nodes[a];
    out.append(py::make_tuple(meshio_type(shape), cells, vector<long>(end - e, [&](std::size_t i) { return static_cast<long>(e + i); })));
    e = end;
  }
  return out;
}

}  // namespace

void bind_results(py::module_& m) {
  py::class_<JobIncrement, IncrementPtr>(m, "Increment",
                                          "The results of one converged increment (owned; arrays are read-only).")
      .def_property_readonly("step", [](const JobIncrement& i) { return i.results.step; }, "1-based step number")
      .def_property_readonly("step_name", [](const JobIncrement& i) { return i.model->steps.at(static_cast<std::size_t>(i.results.step - 1)).name; })
      .def_property_readonly("increment", [](const JobIncrement& i) { return i.results.increment; }, "1-based within the step")
      .def_property_readonly("time", [](const JobIncrement& i) { return i.results.total_time; }, "total time")
      .def_property_readonly("step_time", [](const JobIncrement& i) { return i.results.step_time; })
      .def_property_readonly("iterations", [](const JobIncrement& i) { return i.results.iterations; })
      .def_property_readonly("node_labels", [](const JobIncrement& i) { return vector<int>(i.model->node_ids.size(), [&](std::size_t k) { return i.model->node_ids[k]; }); })
      .def_property_readonly("X", [](py::object self) { const auto& i = self.cast<const JobIncrement&>(); return view(i.model->coords, 2, self); }, "reference coordinates (n, 2)")
      .def_property_readonly("U", [](py::object self) { return view(self.cast<const JobIncrement&>().results.displacement, 2, self); }, "displacements (n, 2)")
      .def_property_readonly("RF", [](py::object self) { return view(self.cast<const JobIncrement&>().results.reaction, 2, self); }, "reaction forces (n, 2); 0 where no dof is prescribed")
      .def_property_readonly("S_nodal", [](py::object self) { return view(self.cast<const JobIncrement&>().results.nodal_stress, 4, self); }, "Cauchy stress averaged at the nodes (n, 4): xx, yy, zz, xy")
      .def_property_readonly("E_nodal", [](py::object self) { return view(self.cast<const JobIncrement&>().results.nodal_strain, 4, self); }, "strain averaged at the nodes (n, 4)")
      .def_property_readonly("element_labels", [](const JobIncrement& i) { return py::array_t<int>(py::cast(point_rows(i).element)); }, "element of each integration point (p,)")
      .def_property_readonly("integration_points", [](const JobIncrement& i) { return py::array_t<int>(py::cast(point_rows(i).point)); }, "1-based point number within its element (p,)")
      .def_property_readonly("S", [](const JobIncrement& i) {
        const PointRows r = point_rows(i);
        return matrix(r.values.size(), 4, [&](std::size_t p, std::size_t k) { return r.values[p]->stress[k]; });
      }, "Cauchy stress at the integration points (p, 4): xx, yy, zz, xy")
      .def_property_readonly("E", [](const JobIncrement& i) {
        const PointRows r = point_rows(i);
        return matrix(r.values.size(), 4, [&](std::size_t p, std::size_t k) { return r.values[p]->strain[k]; });
      }, "strain at the integration points (p, 4); tensor shear")
      .def_property_readonly("point_coordinates", [](const JobIncrement& i) {
        const PointRows r = point_rows(i);
        return matrix(r.values.size(), 2, [&](std::size_t p, std::size_t k) { return r.values[p]->x[static_cast<Eigen::Index>(k)]; });
      }, "current positions of the integration points (p, 2)")
      .def_property_readonly("multipliers", [](const JobIncrement& i) {
        py::dict d;
        for (const auto& v : i.results.multipliers) insert_unique(d, v.owner, multiplier_object(*i.model, v));
        return d;
      }, "{constraint name: its multipliers, f and nodal forces}")
      .def_property_readonly("contact", [](const JobIncrement& i) {
        py::dict d;
        for (const auto& p : i.results.contact) insert_unique(d, p.name, contact_object(*i.model, p));
        return d;
      }, "{contact pair name: state per slave node}")
      .def("_cell_blocks", [](const JobIncrement& i) { return cell_blocks(*i.model); })
      .def("__repr__", [](const JobIncrement& i) {
        return "<tether.Increment step " + std::to_string(i.results.step) + " increment " + std::to_string(i.results.increment) +
               " time " + std::to_string(i.results.total_time) + ">";
      });
}

}  // namespace tether::python
