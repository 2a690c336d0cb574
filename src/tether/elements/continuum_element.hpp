#pragma once
/// \file 2D continuum element (plane strain, plane stress, axisymmetric) of any
/// supported shape, small strain or total Lagrangian finite strain.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/fem/quadrature.hpp"
#include "tether/fem/shape_functions.hpp"
#include "tether/elements/mass_matrix.hpp"
#include "tether/elements/material_point.hpp"
#include "tether/materials/constitutive_model.hpp"
#include "tether/model/element_type.hpp"
#include "tether/model/results.hpp"
#include "tether/model/temperature_data.hpp"

namespace tether {

/// Isoparametric displacement element. Residual r = f_int (internal force,
/// integrated over the reference configuration), tangent dr/du including the
/// geometric stiffness under NLGEOM. Axisymmetric forces are totals over
/// 2 pi radians, as in ABAQUS. See docs/theory/elements.md.
class ContinuumElement final : public Contribution {
 public:
  /// label: user id for messages; node_indices: mesh node indices (dofs via
  /// DofMap::displacement), ABAQUS order; node_coords: the mesh's table of
  /// reference coordinates [length], indexed by node index (Model::coords): the
  /// element reads its nodes' coordinates from it through node_indices and
  /// keeps a pointer to it, so the table must outlive the element and not be
  /// resized or moved (a temporary is refused at compile time); material: must
  /// outlive the element; thickness:
  /// out-of-plane thickness [length] for plane strain/stress, ignored for
  /// axisymmetry. Throws ModelError naming the element when the node count does
  /// not match the type, a node index is outside node_coords, the type is
  /// unsupported, the reference Jacobian is not
  /// positive at an integration point (inverted or degenerate element, or
  /// clockwise node order), an axisymmetric point lies at r <= 0, or the
  /// thickness is not positive. material_data: the `*MATERIAL` the element is
  /// made of, read by mass() only (its density, name and deck line); must
  /// outlive the element; nullptr (or no `*DENSITY` in it) is fine for static
  /// analysis, mass() then throws.
  ContinuumElement(int label, const ElementType& type, std::span<const int> node_indices,
                   const std::vector<Eigen::Vector2d>& node_coords, const ConstitutiveModel& material,
                   double thickness, const DofMap& dofs, const MaterialData* material_data = nullptr);
  /// The element keeps a pointer into node_coords: a temporary table would dangle.
  ContinuumElement(int, const ElementType&, std::span<const int>, std::vector<Eigen::Vector2d>&&,
                   const ConstitutiveModel&, double, const DofMap&, const MaterialData* = nullptr) = delete;

  [[nodiscard]] std::span<const int> dofs() const override {
    return {storage_.get(), static_cast<std::size_t>(2 * n_nodes_)};
  }

  /// Small strain when !s.nlgeom, total Lagrangian when s.nlgeom. Throws
  /// ModelError naming the element when det F <= 0 at an integration point.
  void evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const override;

  /// "element 12 (CPE4)".
  [[nodiscard]] std::string describe() const override;
  /// The material's word (ConstitutiveModel::symmetric_tangent); the
  /// geometric stiffness under NLGEOM is symmetric.
  [[nodiscard]] bool symmetric_tangent(bool nlgeom) const override { return material_->symmetric_tangent(nlgeom); }
  /// Small strain with a material whose small-strain law is linear
  /// (LinearElastic, NeoHooke's initial elasticity): linear. Under NLGEOM or
  /// with a history (plasticity): not.
  [[nodiscard]] bool linear_in_u(bool nlgeom) const override {
    return !nlgeom && material_->linear_small_strain();
  }
  /// False for an elastic material (linear_small_strain: its stress reads no
  /// time) without history and without temperatures: the residual is then a
  /// function of u alone. True with a temperature field (thermal strain).
  [[nodiscard]] bool residual_depends_on_time() const override {
    return temperatures_ != nullptr || has_history() || !material_->linear_small_strain();
  }

  /// Material history. Each integration point owns a committed record
  /// (stress, strain, elastic energy, accumulated dissipation and the
  /// material's state); evaluate() computes the trial state from it and the
  /// current displacements and stores nothing, so a cut-back needs no
  /// restore. commit() evaluates the points at s.u and makes that trial state
  /// the committed one, stamped with the element's displacements at s.u and
  /// the total time.
  /// Nothing is kept for a material without history (n_state() == 0).
  void commit(const EvaluationState& s) override;
  /// Restart: a tag, the record sizes, the records and the stamp (displacements, time) (nothing
  /// without history).
  void save_state(std::vector<double>& out) const override;
  void load_state(std::span<const double>& in) override;
  /// True when the material keeps a history at the integration points.
  [[nodiscard]] bool has_history() const { return history_ != nullptr; }
  /// Plastic dissipation up to the state s [energy] (total over 2 pi for
  /// axisymmetry): the committed records' when they were committed at s.u,
  /// else theirs plus the increment to the trial state of s.u (as
  /// point_values); 0 without history.
  [[nodiscard]] double plastic_dissipation(const EvaluationState& s) const;
  /// Plastic dissipation of the increment that ends at s [energy]: the trial
  /// state's dissipation beyond the committed records (call it before
  /// commit(s); 0 once the records are committed at s, and without history).
  /// Equals plastic_dissipation(s) minus its value at the committed state.
  [[nodiscard]] double plastic_dissipation_increment(const EvaluationState& s) const;

  /// Nodal temperatures the element reads (must outlive it; nullptr, the
  /// default: every temperature is 0). The point temperature and initial
  /// temperature are the shape-function interpolations of the nodal values,
  /// handed to the material in PointContext (thermal strain,
  /// temperature-dependent elasticity).
  void set_temperatures(const NodalTemperatureField* field) { temperatures_ = field; }

  [[nodiscard]] int label() const { return label_; }
  /// The name describe() gives the element (default: its label); the
  /// analysis sets `INSTANCE.label` for an element of an ABAQUS/CAE instance.
  /// A name equal to the label's digits is not stored (describe() prints the
  /// same text without it).
  void set_name(std::string name);
  [[nodiscard]] const ElementType& type() const { return *type_; }
  [[nodiscard]] int n_points() const { return n_points_; }
  /// Mesh node indices, ABAQUS order.
  [[nodiscard]] std::span<const int> nodes() const {
    return {dofs().data() + 2 * n_nodes_, static_cast<std::size_t>(n_nodes_)};
  }

  /// Stored strain energy [energy] (total over 2 pi for axisymmetry); its
  /// gradient with respect to the element dofs is the residual.
  [[nodiscard]] double strain_energy(const EvaluationState& s) const;

  /// Values at the integration points, ABAQUS order: Cauchy stress; small
  /// strain, or Green-Lagrange strain under NLGEOM (tensor shear); current
  /// position X + u; PEEQ and plastic strain; the thermal strain THE (zero
  /// unless the material is a ThermalModel). With a history they are the
  /// converged trial state of s.u: read from the committed records when they
  /// were committed at s.u (the element's displacements equal the stamp),
  /// else evaluated from the committed history, as evaluate() does -- so
  /// results built before and after commit() are the same, bit for bit.
  void point_values(const EvaluationState& s, std::vector<PointValues>& out) const;

  /// Plane stress under NLGEOM: the thickness stretch F33 = h/h0 at the point
  /// `xi` (reference coordinates of the element), and dF33/du over dofs()
  /// (local order) into `dF33_du` (resized). The points are evaluated at s.u
  /// from the committed records, as evaluate() does (so a plastic point's
  /// thickness follows its history, a thermal one's its temperature), and
  /// their F33 carried to `xi` by the polynomial that extrapolates point
  /// values to the nodes (exact for a uniform state). Throws ModelError naming
  /// the element when the element is not plane stress, or as evaluate().
  double thickness_stretch(const EvaluationState& s, const Eigen::Vector2d& xi, Eigen::VectorXd& dF33_du) const;

  /// Mass matrix over dofs() [mass] (2n x 2n, local dof order; lumped: diagonal),
  /// from the reference configuration, the material's density and the thickness
  /// (totals over 2 pi for axisymmetry): constant, also under NLGEOM. See
  /// elements/mass_matrix.hpp. Throws ModelError naming the element and its
  /// material when the material has no `*DENSITY`, or when det J <= 0 (R <= 0)
  /// at a point of the mass rule.
  void mass(MassKind kind, Eigen::MatrixXd& out) const;

  /// Extrapolates point values to the element's nodes (stress and strain),
  /// ABAQUS-like (see fem/extrapolation.hpp). `points` has n_points() entries.
  void extrapolate_to_nodes(const std::vector<PointValues>& points, std::vector<Tensor4>& nodal_stress,
                            std::vector<Tensor4>& nodal_strain) const;
  /// As extrapolate_to_nodes, for the thermal strain THE.
  void extrapolate_thermal_to_nodes(const std::vector<PointValues>& points,
                                    std::vector<Tensor4>& nodal_thermal_strain) const;
  /// As extrapolate_to_nodes, for PEEQ and the plastic strain PE.
  void extrapolate_plastic_to_nodes(const std::vector<PointValues>& points, std::vector<double>& nodal_peeq,
                                    std::vector<Tensor4>& nodal_plastic_strain) const;
  /// As extrapolate_to_nodes, for the first `n` state variables SDV of each
  /// point (zeros beyond a point's own): nodal[a * n + k] for node a.
  void extrapolate_sdv_to_nodes(const std::vector<PointValues>& points, int n, std::vector<double>& nodal) const;

 private:
  /// Geometry of one integration point, recomputed from the reference
  /// coordinates at each use (storing it took 14 doubles per point of a CPE4,
  /// more than half of the element's memory).
  struct PointGeometry {
    ShapeVector N;    ///< shape functions
    ShapeGradient G;  ///< dN/dX: column 0 = d/dX, column 1 = d/dY
    double dV = 0;    ///< weight * det J * (thickness, or 2 pi R)
    double R = 0;     ///< X of the point (the radius for axisymmetry)
    double Y = 0;     ///< Y of the point
  };
  /// Reference coordinates of the element's nodes [length], ABAQUS order
  /// (the first n_nodes_ entries), gathered from the mesh's table. NN: the
  /// node count when the caller knows it at compile time (the kernels), else
  /// Eigen::Dynamic; the same values either way.
  using NodeCoordinates = std::array<Eigen::Vector2d, kMaxElementNodes>;
  template <int NN = Eigen::Dynamic>
  [[nodiscard]] NodeCoordinates reference_coords() const;
  /// Fills `g` for integration point q from the nodes' reference coordinates X
  /// (reference_coords()); returns det J (checked > 0 at construction). NN as
  /// for reference_coords: the same values, bit for bit, in fewer instructions.
  template <int NN = Eigen::Dynamic>
  double point_geometry(int q, const NodeCoordinates& X, PointGeometry& g) const;
  /// Local displacement vector (u_0x, u_0y, u_1x, ...).
  void gather(const Eigen::VectorXd& u, Eigen::Ref<Eigen::VectorXd> ue) const;
  /// Evaluates point q (geometry g) from local displacements ue and its
  /// committed history; the trial state goes to `trial` (n_state() values).
  /// `mean`: for a hybrid element the element_mean() of ue (ignored otherwise).
  void material_point(int q, const PointGeometry& g, const double* ue, const EvaluationState& s, MaterialPoint& mp,
                      std::span<double> trial, double mean = 0) const;
  /// Hybrid (mean-dilatation) element: theta = v/V under NLGEOM, else the
  /// mean volumetric strain e_bar, at the local displacements ue; 0 for any
  /// other element. See continuum_element_hybrid.cpp.
  [[nodiscard]] double element_mean(const double* ue, bool nlgeom) const;
  /// Residual and tangent of a hybrid element, finite strain (F-bar with the
  /// element's theta) and small strain (B-bar).
  void evaluate_hybrid_finite(const double* ue, const EvaluationState& s, LocalSystem& out, bool need_tangent) const;
  /// material_point() of a hybrid element: the material sees F_bar =
  /// (theta/J)^(1/3) F, or eps_bar, with theta or e_bar = `mean`.
  void hybrid_point(int q, const PointGeometry& g, const Eigen::Matrix2d& H, double hoop, double mean,
                    const EvaluationState& s, MaterialPoint& mp, std::span<double> trial) const;
  void evaluate_hybrid_small(const double* ue, const EvaluationState& s, LocalSystem& out, bool need_tangent) const;
  /// What the material is told about point q (geometry g) in state s.
  [[nodiscard]] PointContext context(const EvaluationState& s, int q, const PointGeometry& g) const;
  /// Point q's material state in the committed records (empty without history).
  [[nodiscard]] std::span<const double> committed_state(int q) const;
  /// True when the committed records were committed at the local
  /// displacements ue and the total time `total_time` (a rate-dependent user
  /// material answers differently at the same strain and another time).
  [[nodiscard]] bool committed_at(const Eigen::Ref<const Eigen::VectorXd>& ue, double total_time) const;
  template <int NN>
  void evaluate_kernel(const double* ue, const EvaluationState& s, LocalSystem& out, bool need_tangent) const;

  /// Layout of a point's committed record: stress (6), strain (6), elastic
  /// energy density, accumulated dissipation density, material state.
  static constexpr int kRecordStress = 0, kRecordStrain = 6, kRecordEnergy = 12, kRecordDissipation = 13,
                       kRecordState = 14;

  /// Material state values per integration point (0 without history).
  [[nodiscard]] int n_state() const { return history_ == nullptr ? 0 : history_->n_state; }

  /// The committed records and their stamp; only for a material with history.
  struct History {
    int n_state = 0;                  ///< material state values per point (> 0)
    std::vector<double> records;      ///< n_points_ x (kRecordState + n_state)
    std::vector<double> committed_u;  ///< local displacements of the records (the stamp, with the time)
    double committed_time = 0;        ///< total time of the records (the stamp, with committed_u)
  };

  // The object is kept small (88 bytes; one per mesh element, 115k at the
  // 230k-dof Hertz deck): the type is shared, the name kept only when it is
  // not the label, the reference coordinates read from the mesh's table, the
  // per-node arrays in one block, and the history (with its state count) only
  // for a material that has one. See docs/performance.md, "ContinuumElement
  // and the model's tables made smaller" and "Elements read the mesh's
  // coordinates".
  int label_;
  QuadratureRule rule_;
  std::uint8_t n_nodes_;
  std::uint8_t n_points_;
  const ElementType* type_;            ///< interned (intern_element_type)
  std::unique_ptr<const std::string> name_;  ///< set_name(); null: the label
  /// One block: the 2 n_nodes_ dofs (x, y per node), then the n_nodes_ mesh
  /// node indices (int).
  std::unique_ptr<int[]> storage_;
  /// The mesh's reference coordinates, indexed by node index (not owned).
  const Eigen::Vector2d* node_coords_;
  const ConstitutiveModel* material_;
  const MaterialData* material_data_;  ///< for mass(); may be null
  double thickness_;
  std::unique_ptr<History> history_;   ///< null without history (n_state() == 0)
  const NodalTemperatureField* temperatures_ = nullptr;  ///< nodal temperatures; null: all 0
};

}  // namespace tether
