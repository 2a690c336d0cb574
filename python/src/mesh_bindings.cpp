// Editing a model's mesh and sections from Python, for parameter studies:
// connectivity as NumPy, moving nodes (checked like the deck reader checks
// them), new node and element sets, materials copied under a new name,
// sections re-pointed at another material or thickness, new sections.

#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>

#include "bindings.hpp"
#include "tether/io/model_checks.hpp"
#include "tether/model/model.hpp"

namespace tether::python {

namespace {

using ModelPtr = std::shared_ptr<Model>;

/// A *SOLID SECTION of the model (a (model, index) handle like the others).
struct SectionRef {
  ModelPtr model;
  std::size_t index;
  [[nodiscard]] SolidSection& get() const { return model->sections.at(index); }
};

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

/// Index of material `name` (any case); KeyError when there is none.
int material_index(const Model& md, const std::string& name) {
  const std::string key = upper(name);
  for (std::size_t k = 0; k < md.materials.size(); ++k)
    if (md.materials[k].name == key) return static_cast<int>(k);
  throw py::key_error("no material " + key);
}

/// Node indices of `labels`, sorted and unique when `sorted`; KeyError naming an unknown label.
std::vector<int> node_indices(const Model& md, const std::vector<int>& labels, bool sorted) {
  std::vector<int> out;
  for (int label : labels) {
    const auto it = md.node_index.find(label);
    if (it == md.node_index.end()) throw py::key_error("no node " + std::to_string(label));
    out.push_back(it->second);
  }
  if (sorted) std::sort(out.begin(), out.end()), out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> element_indices(const Model& md, const std::vector<int>& labels) {
  std::vector<int> out;
  for (int label : labels) {
    const auto it = md.element_index.find(label);
    if (it == md.element_index.end()) throw py::key_error("no element " + std::to_string(label));
    out.push_back(it->second);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// ValueError naming the first element of `elements` that is inverted or
/// degenerate, or has a node at r < 0 when axisymmetric (the reader's checks).
void check_elements(const Model& md, const std::vector<int>& elements) {
  for (int k : elements) {
    const Element& e = md.elements[static_cast<std::size_t>(k)];
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int n : e.nodes) {
      const Eigen::Vector2d& x = md.coords[static_cast<std::size_t>(n)];
      if (!x.allFinite()) throw py::value_error("node " + std::to_string(md.node_ids[static_cast<std::size_t>(n)]) + ": coordinates not finite");
      if (e.type.family == Family::Axisymmetric && x.x() < 0)
        throw py::value_error("axisymmetric element " + std::to_string(e.id) + ": node " +
                              std::to_string(md.node_ids[static_cast<std::size_t>(n)]) + " at r = x < 0");
      xmin = std::min(xmin, x.x()), xmax = std::max(xmax, x.x()), ymin = std::min(ymin, x.y()), ymax = std::max(ymax, x.y());
    }
    const double scale = std::max((xmax - xmin) * (xmax - xmin), (ymax - ymin) * (ymax - ymin));
    for (double det : deck::corner_jacobians(md, e))
      if (!(det > 1e-12 * scale))
        throw py::value_error("element " + std::to_string(e.id) + " would be inverted or degenerate (corner Jacobian " +
                              std::to_string(det) + ")");
  }
}

/// Moves node indices `nodes` to the rows of `xy` ((len, 2)); the model is
/// unchanged when an element they belong to would become invalid.
void move_nodes(Model& md, const std::vector<int>& nodes, const py::array_t<double, py::array::c_style | py::array::forcecast>& xy) {
  if (xy.ndim() != 2 || xy.shape(0) != static_cast<py::ssize_t>(nodes.size()) || xy.shape(1) != 2)
    throw py::value_error("coordinates: expected shape (" + std::to_string(nodes.size()) + ", 2)");
  std::vector<char> moved(md.coords.size(), 0);
  std::vector<Eigen::Vector2d> old;
  auto v = xy.unchecked<2>();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    Eigen::Vector2d& x = md.coords[static_cast<std::size_t>(nodes[i])];
    old.push_back(x);
    x = {v(static_cast<py::ssize_t>(i), 0), v(static_cast<py::ssize_t>(i), 1)};
    moved[static_cast<std::size_t>(nodes[i])] = 1;
  }
  std::vector<int> touched;
  for (std::size_t k = 0; k < md.elements.size(); ++k)
    for (int n : md.elements[k].nodes)
      if (moved[static_cast<std::size_t>(n)]) {
        touched.push_back(static_cast<int>(k));
        break;
      }
  try {
    check_elements(md, touched);
  } catch (...) {
    for (std::size_t i = nodes.size(); i-- > 0;) md.coords[static_cast<std::size_t>(nodes[i])] = old[i];
    throw;
  }
}

void add_set(std::map<std::string, std::vector<int>>& sets, const std::string& name, std::vector<int> members,
             const char* what) {
  const std::string key = upper(name);
  if (key.empty()) throw py::value_error(std::string(what) + " set: empty name");
  if (sets.count(key)) throw py::value_error(std::string(what) + " set " + key + " exists already");
  sets[key] = std::move(members);
}

/// The element labels that have section `index`.
py::array_t<int> section_elements(const Model& md, std::size_t index) {
  std::vector<int> out;
  for (const Element& e : md.elements)
    if (e.section == static_cast<int>(index)) out.push_back(e.id);
  return py::array_t<int>(py::cast(out));
}

void bind_section(py::module_& m) {
  py::class_<SectionRef>(m, "Section", "A *SOLID SECTION (changes go into the model).")
      .def_property_readonly("elset", [](const SectionRef& s) { return s.get().elset; })
      .def_property(
          "material", [](const SectionRef& s) { return s.model->materials.at(static_cast<std::size_t>(s.get().material)).name; },
          [](const SectionRef& s, const std::string& name) { s.get().material = material_index(*s.model, name); },
          "name of its material (set: any material of the model)")
      .def_property(
          "thickness", [](const SectionRef& s) { return s.get().thickness; },
          [](const SectionRef& s, double t) {
            if (!(t > 0)) throw py::value_error("the thickness must be > 0");
            s.get().thickness = t;
          },
          "out-of-plane thickness [length] (ignored by CAX elements)")
      .def_property_readonly("element_labels", [](const SectionRef& s) { return section_elements(*s.model, s.index); },
                             "the elements that have this section")
      .def("__repr__", [](const SectionRef& s) {
        return "<tether.Section " + s.get().elset + ": " +
               s.model->materials.at(static_cast<std::size_t>(s.get().material)).name + ">";
      });
}

}  // namespace

void bind_mesh_editing(py::module_& m, py::class_<Model, std::shared_ptr<Model>>& model) {
  bind_section(m);
  model
      .def_property(
          "coordinates",
          [](const Model& md) {
            return matrix(md.coords.size(), 2,
                          [&](std::size_t i, std::size_t j) { return md.coords[i][static_cast<Eigen::Index>(j)]; });
          },
          [](Model& md, const py::array_t<double, py::array::c_style | py::array::forcecast>& xy) {
            std::vector<int> all(md.coords.size());
            for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
            move_nodes(md, all, xy);
          },
          "reference coordinates (n, 2) in node_labels order (a copy; assign an array to move the nodes)")
      .def_property_readonly("element_nodes",
                             [](const Model& md) {
                               std::size_t k = 0;
                               for (const Element& e : md.elements) k = std::max(k, e.nodes.size());
                               py::array_t<int> a({md.elements.size(), k});
                               auto v = a.mutable_unchecked<2>();
                               for (std::size_t i = 0; i < md.elements.size(); ++i)
                                 for (std::size_t j = 0; j < k; ++j)
                                   v(i, j) = j < md.elements[i].nodes.size()
                                                 ? md.node_ids[static_cast<std::size_t>(md.elements[i].nodes[j])]
                                                 : -1;
                               return a;
                             },
                             "(n_elements, k) node labels of each element in ABAQUS order, k the most nodes of an "
                             "element, padded with -1")
      .def(
          "set_coordinates",
          [](Model& md, const std::vector<int>& labels, const py::array_t<double, py::array::c_style | py::array::forcecast>& xy) {
            move_nodes(md, node_indices(md, labels, false), xy);
          },
          py::arg("labels"), py::arg("xy"),
          "Moves the nodes `labels` to the reference coordinates `xy` (len, 2); ValueError (model unchanged) when an "
          "element would be inverted or degenerate")
      .def(
          "add_node_set",
          [](Model& md, const std::string& name, const std::vector<int>& labels) {
            add_set(md.node_sets, name, node_indices(md, labels, true), "node");
          },
          py::arg("name"), py::arg("labels"))
      .def(
          "add_element_set",
          [](Model& md, const std::string& name, const std::vector<int>& labels) {
            add_set(md.element_sets, name, element_indices(md, labels), "element");
          },
          py::arg("name"), py::arg("labels"))
      .def(
          "add_material",
          [](Model& md, const std::string& name, const std::string& copy_of) {
            const std::string key = upper(name);
            if (key.empty()) throw py::value_error("material: empty name");
            for (const MaterialData& d : md.materials)
              if (d.name == key) throw py::value_error("material " + key + " exists already");
            MaterialData copy = md.materials.at(static_cast<std::size_t>(material_index(md, copy_of)));
            copy.name = key;
            md.materials.push_back(std::move(copy));
          },
          py::arg("name"), py::arg("copy_of"), "A new material, a copy of `copy_of` (then change its constants)")
      .def_property_readonly("sections",
                             [](const ModelPtr& md) {
                               py::list l;
                               for (std::size_t k = 0; k < md->sections.size(); ++k) l.append(SectionRef{md, k});
                               return l;
                             })
      .def(
          "add_section",
          [](const ModelPtr& md, const std::string& elset, const std::string& material, double thickness) {
            const auto set = md->element_sets.find(upper(elset));
            if (set == md->element_sets.end()) throw py::key_error("no element set " + upper(elset));
            if (!(thickness > 0)) throw py::value_error("the thickness must be > 0");
            SolidSection s;
            s.elset = set->first;
            s.material = material_index(*md, material);
            s.thickness = thickness;
            md->sections.push_back(s);
            const int index = static_cast<int>(md->sections.size()) - 1;
            for (int e : set->second) md->elements[static_cast<std::size_t>(e)].section = index;
            return SectionRef{md, md->sections.size() - 1};
          },
          py::arg("elset"), py::arg("material"), py::arg("thickness") = 1.0,
          "Gives the elements of `elset` a new section (they leave the one they had)");
}

}  // namespace tether::python
