// tether.Model and the parts of it a parameter study changes: materials,
// steps, concentrated loads, prescribed displacements, pressures (the mesh
// and the sections: mesh_bindings.cpp).
//
// Python holds the model through a shared pointer; a material, step or load
// object is a (model, index) handle, so it stays valid however long Python
// keeps it and always reads and writes the model's current value.

#include <pybind11/stl.h>

#include <stdexcept>

#include "bindings.hpp"
#include "tether/model/model.hpp"

namespace tether::python {

namespace {

using ModelPtr = std::shared_ptr<Model>;

struct MaterialRef {
  ModelPtr model;
  std::size_t index;
  [[nodiscard]] MaterialData& get() const { return model->materials.at(index); }
};

struct InteractionRef {
  ModelPtr model;
  std::size_t index;
  [[nodiscard]] SurfaceInteraction& get() const { return model->interactions.at(index); }
};

struct StepRef {
  ModelPtr model;
  std::size_t index;
  [[nodiscard]] Step& get() const { return model->steps.at(index); }
};

/// Entry `index` of a list of step `step` (`List` selects cloads, boundary or pressures).
template <auto List>
struct StepEntryRef {
  ModelPtr model;
  std::size_t step, index;
  [[nodiscard]] auto& get() const { return (model->steps.at(step).*List).at(index); }
};
using CloadRef = StepEntryRef<&Step::cloads>;
using BoundaryRef = StepEntryRef<&Step::boundary>;
using PressureRef = StepEntryRef<&Step::pressures>;

/// The ABAQUS dof number (1, 2, 6) of a stored component (0, 1, 2).
int abaqus_dof(int dof) { return dof == 2 ? 6 : dof + 1; }

void require(bool ok, const std::string& what) {
  if (!ok) throw py::value_error(what);
}

MaterialData::Elastic& elastic(const MaterialRef& m) {
  MaterialData& d = m.get();
  if (!d.elastic) throw py::attribute_error("material " + d.name + " has no *ELASTIC data");
  return *d.elastic;
}

MaterialData::NeoHooke& neo_hooke(const MaterialRef& m) {
  MaterialData& d = m.get();
  if (!d.neo_hooke) throw py::attribute_error("material " + d.name + " has no *HYPERELASTIC, NEO HOOKE data");
  return *d.neo_hooke;
}

void bind_material(py::module_& m) {
  py::class_<MaterialRef>(m, "Material", "A *MATERIAL of the model (changes go into the model).")
      .def_property_readonly("name", [](const MaterialRef& r) { return r.get().name; })
      .def_property(
          "young", [](const MaterialRef& r) { return elastic(r).young; },
          [](const MaterialRef& r, double e) {
            require(e > 0, "Young's modulus must be > 0");
            elastic(r).young = e;
          },
          "E of *ELASTIC [stress]")
      .def_property(
          "poisson", [](const MaterialRef& r) { return elastic(r).poisson; },
          [](const MaterialRef& r, double nu) {
            require(nu > -1 && nu < 0.5, "Poisson's ratio must lie in (-1, 0.5)");
            elastic(r).poisson = nu;
          },
          "nu of *ELASTIC [-]")
      .def_property(
          "c10", [](const MaterialRef& r) { return neo_hooke(r).c10; },
          [](const MaterialRef& r, double c) {
            require(c > 0, "C10 must be > 0");
            neo_hooke(r).c10 = c;
          },
          "C10 = mu/2 of *HYPERELASTIC, NEO HOOKE [stress]")
      .def_property(
          "d1", [](const MaterialRef& r) { return neo_hooke(r).d1; },
          [](const MaterialRef& r, double d) {
            require(d > 0, "D1 must be > 0 (incompressible is not supported)");
            neo_hooke(r).d1 = d;
          },
          "D1 = 2/K of *HYPERELASTIC, NEO HOOKE [1/stress]")
      .def_property(
          "density", [](const MaterialRef& r) { return r.get().density; },
          [](const MaterialRef& r, std::optional<double> rho) {
            require(!rho || *rho > 0, "the density must be > 0");
            r.get().density = rho;
          },
          "*DENSITY [mass/volume], None when not given")
      .def("__repr__", [](const MaterialRef& r) { return "<tether.Material " + r.get().name + ">"; });
}

const char* law_name(PressureOverclosure::Law law) {
  switch (law) {
    case PressureOverclosure::Law::Hard: return "hard";
    case PressureOverclosure::Law::Linear: return "linear";
    case PressureOverclosure::Law::Exponential: return "exponential";
    case PressureOverclosure::Law::Tabular: return "tabular";
  }
  return "?";
}

FrictionData& friction(const InteractionRef& r) {
  SurfaceInteraction& i = r.get();
  if (!i.friction) throw py::attribute_error("interaction " + i.name + " has no *FRICTION");
  return *i.friction;
}

void bind_interaction(py::module_& m) {
  py::class_<InteractionRef>(m, "Interaction", "A *SURFACE INTERACTION (changes go into the model).")
      .def_property_readonly("name", [](const InteractionRef& r) { return r.get().name; })
      .def_property_readonly("law", [](const InteractionRef& r) { return law_name(r.get().behavior.law); },
                             "pressure-overclosure law: hard, linear, exponential, tabular")
      .def_property(
          "stiffness", [](const InteractionRef& r) { return r.get().behavior.stiffness; },
          [](const InteractionRef& r, double k) {
            require(r.get().behavior.law == PressureOverclosure::Law::Linear, "stiffness: the law is not LINEAR");
            require(k > 0, "the contact stiffness must be > 0");
            r.get().behavior.stiffness = k;
          },
          "K of PRESSURE-OVERCLOSURE=LINEAR [pressure/length]")
      .def_property_readonly("has_friction", [](const InteractionRef& r) { return r.get().friction.has_value(); })
      .def_property(
          "mu", [](const InteractionRef& r) { return friction(r).mu; },
          [](const InteractionRef& r, double mu) {
            require(mu >= 0, "the friction coefficient must be >= 0");
            friction(r).mu = mu;
          },
          "Coulomb friction coefficient of *FRICTION")
      .def("__repr__", [](const InteractionRef& r) { return "<tether.Interaction " + r.get().name + ">"; });
}

void bind_loads(py::module_& m) {
  py::class_<CloadRef>(m, "ConcentratedLoad", "A *CLOAD entry of a step.")
      .def_property_readonly("node", [](const CloadRef& r) { return r.model->node_ids.at(r.get().node); })
      .def_property_readonly("dof", [](const CloadRef& r) { return abaqus_dof(r.get().dof); }, "1, 2 or 6")
      .def_property(
          "magnitude", [](const CloadRef& r) { return r.get().magnitude; },
          [](const CloadRef& r, double v) { r.get().magnitude = v; }, "[force] ([force x length] for dof 6)");
  py::class_<BoundaryRef>(m, "Boundary", "A prescribed displacement component of a step (*BOUNDARY).")
      .def_property_readonly("node", [](const BoundaryRef& r) { return r.model->node_ids.at(r.get().node); })
      .def_property_readonly("dof", [](const BoundaryRef& r) { return abaqus_dof(r.get().dof); }, "1, 2 or 6")
      .def_property(
          "value", [](const BoundaryRef& r) { return r.get().value; },
          [](const BoundaryRef& r, double v) { r.get().value = v; }, "[length] ([rad] for dof 6)");
  py::class_<PressureRef>(m, "Pressure", "A *DLOAD / *DSLOAD pressure on an element face of a step.")
      .def_property_readonly("element",
                             [](const PressureRef& r) { return r.model->elements.at(r.get().face.element).id; })
      .def_property_readonly("face", [](const PressureRef& r) { return r.get().face.face + 1; }, "1 = S1, ...")
      .def_property(
          "magnitude", [](const PressureRef& r) { return r.get().magnitude; },
          [](const PressureRef& r, double v) { r.get().magnitude = v; }, "[force/area], > 0 pushes into the face");
}

template <class Ref, auto List>
py::list entries(const StepRef& s) {
  py::list out;
  for (std::size_t k = 0; k < (s.get().*List).size(); ++k) out.append(Ref{s.model, s.index, k});
  return out;
}

void bind_step(py::module_& m) {
  py::class_<StepRef>(m, "Step", "A *STEP of the model (changes go into the model).")
      .def_property_readonly("name", [](const StepRef& s) { return s.get().name; })
      .def_property(
          "nlgeom", [](const StepRef& s) { return s.get().nlgeom; }, [](const StepRef& s, bool v) { s.get().nlgeom = v; })
      .def_property(
          "period", [](const StepRef& s) { return s.get().period; },
          [](const StepRef& s, double v) {
            require(v > 0, "the step period must be > 0");
            s.get().period = v;
          },
          "step time period")
      .def_property(
          "initial_increment", [](const StepRef& s) { return s.get().initial_increment; },
          [](const StepRef& s, double v) {
            require(v >= 0, "the initial increment must be >= 0");
            s.get().initial_increment = v;
          })
      .def_property(
          "min_increment", [](const StepRef& s) { return s.get().min_increment; },
          [](const StepRef& s, double v) {
            require(v >= 0, "the minimum increment must be >= 0");
            s.get().min_increment = v;
          })
      .def_property(
          "max_increment", [](const StepRef& s) { return s.get().max_increment; },
          [](const StepRef& s, double v) {
            require(v >= 0, "the maximum increment must be >= 0");
            s.get().max_increment = v;
          })
      .def_property(
          "max_increments", [](const StepRef& s) { return s.get().max_increments; },
          [](const StepRef& s, int v) {
            require(v > 0, "INC must be > 0");
            s.get().max_increments = v;
          },
          "INC=")
      .def_property(
          "direct", [](const StepRef& s) { return s.get().direct; }, [](const StepRef& s, bool v) { s.get().direct = v; },
          "fixed increments (DIRECT)")
      .def_property_readonly("cloads", &entries<CloadRef, &Step::cloads>)
      .def_property_readonly("boundary", &entries<BoundaryRef, &Step::boundary>)
      .def_property_readonly("pressures", &entries<PressureRef, &Step::pressures>)
      .def("__repr__", [](const StepRef& s) { return "<tether.Step " + std::to_string(s.index + 1) + " " + s.get().name + ">"; });
}

/// The labels of `indices` (node or element indices).
py::array_t<int> labels_of(const std::vector<int>& indices, const std::vector<int>& labels) {
  return vector<int>(indices.size(), [&](std::size_t i) { return labels[static_cast<std::size_t>(indices[i])]; });
}

std::vector<int> element_labels(const Model& model) {
  std::vector<int> out;
  for (const Element& e : model.elements) out.push_back(e.id);
  return out;
}

void bind_model_class(py::module_& m) {
  py::class_<Model, std::shared_ptr<Model>> model(m, "Model", "A model read from a deck: mesh, materials, constraints, steps.");
  bind_mesh_editing(m, model);
  model
      .def_readonly("heading", &Model::heading)
      .def_readonly("deck_path", &Model::deck_path)
      .def_property_readonly("n_nodes", &Model::n_nodes)
      .def_property_readonly("n_elements", &Model::n_elements)
      .def_property_readonly("node_labels",
                             [](const Model& md) { return vector<int>(md.node_ids.size(), [&](std::size_t i) { return md.node_ids[i]; }); })
      .def_property_readonly("element_labels", [](const Model& md) { return py::array_t<int>(py::cast(element_labels(md))); })
      .def_property_readonly("element_types",
                             [](const Model& md) {
                               std::vector<std::string> out;
                               for (const Element& e : md.elements) out.emplace_back(e.type.name);
                               return out;
                             })
      .def_property_readonly("node_sets",
                             [](const Model& md) {
                               py::dict d;
                               for (const auto& [name, nodes] : md.node_sets) d[py::str(name)] = labels_of(nodes, md.node_ids);
                               return d;
                             })
      .def_property_readonly("element_sets",
                             [](const Model& md) {
                               py::dict d;
                               const std::vector<int> labels = element_labels(md);
                               for (const auto& [name, elements] : md.element_sets) d[py::str(name)] = labels_of(elements, labels);
                               return d;
                             })
      .def_property_readonly("materials",
                             [](const std::shared_ptr<Model>& md) {
                               py::dict d;
                               for (std::size_t k = 0; k < md->materials.size(); ++k)
                                 d[py::str(md->materials[k].name)] = MaterialRef{md, k};
                               return d;
                             }, "{name: Material}, names upper case")
      .def_property_readonly("interactions",
                             [](const std::shared_ptr<Model>& md) {
                               py::dict d;
                               for (std::size_t k = 0; k < md->interactions.size(); ++k)
                                 d[py::str(md->interactions[k].name)] = InteractionRef{md, k};
                               return d;
                             }, "{name: Interaction} of the *SURFACE INTERACTIONs, names upper case")
      .def_property_readonly("steps",
                             [](const std::shared_ptr<Model>& md) {
                               py::list l;
                               for (std::size_t k = 0; k < md->steps.size(); ++k) l.append(StepRef{md, k});
                               return l;
                             })
      .def_property_readonly("constraints",
                             [](const Model& md) {
                               std::vector<std::string> out;
                               for (const auto& c : md.constraints) out.push_back(c.name);
                               return out;
                             }, "names of the constraints")
      .def_property_readonly("contact_pairs",
                             [](const Model& md) {
                               py::list out;
                               for (const auto& c : md.contact_pairs) out.append(py::make_tuple(c.slave, c.master));
                               return out;
                             }, "(slave, master) surface names of each *CONTACT PAIR")
      .def("copy", [](const Model& md) { return std::make_shared<Model>(md); }, "An independent copy.")
      .def("__repr__", [](const Model& md) {
        return "<tether.Model " + md.deck_path + ": " + std::to_string(md.n_nodes()) + " nodes, " +
               std::to_string(md.n_elements()) + " elements, " + std::to_string(md.steps.size()) + " step(s)>";
      });
}

}  // namespace

void bind_model(py::module_& m) {
  bind_material(m);
  bind_interaction(m);
  bind_loads(m);
  bind_step(m);
  bind_model_class(m);
}

}  // namespace tether::python
