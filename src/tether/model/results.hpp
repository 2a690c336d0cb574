#pragma once
/// \file Results of one converged increment: plain data handed to the writers.

#include <Eigen/Core>
#include <optional>
#include <array>
#include <string>
#include <vector>

namespace tether {

/// Symmetric 2D-solid tensor in the order (xx, yy, zz, xy); zz is the
/// out-of-plane (plane) or hoop (axisymmetric) component.
using Tensor4 = std::array<double, 4>;

/// Von Mises equivalent of a (xx, yy, zz, xy) tensor (xz = yz = 0).
double von_mises(const Tensor4& s);

/// Values at one integration point.
struct PointValues {
  Eigen::Vector2d x{0, 0};  ///< current position
  Tensor4 stress{};         ///< Cauchy stress [force/area]
  Tensor4 strain{};         ///< small strain, or Green-Lagrange strain under NLGEOM; tensor shear
  double peeq = 0;          ///< equivalent plastic strain PEEQ [-] (0 for elastic materials)
  Tensor4 plastic_strain{}; ///< plastic strain PE, tensor shear [-] (zero for elastic materials)
  /// AC YIELD: 1 when the point flowed plastically in the increment that
  /// produced these values (dp > 0), else 0; always 0 for elastic and user
  /// (UMAT) materials.
  int ac_yield = 0;
  /// Thermal strain THE [-]: eps_th on the three normal components, no shear
  /// (zero without *EXPANSION). Under NLGEOM too it is eps_th, the thermal
  /// stretch minus one (F_th = (1 + eps_th) I), not a Green-Lagrange measure.
  Tensor4 thermal_strain{};
  /// SDV: a user material's (UMAT's) state variables STATEV, NSTATV values;
  /// empty for tether's own materials.
  std::vector<double> sdv;
};

/// The force a constraint exerts on one node: -sum_k lambda_k df_k/du over
/// the node's two displacement components [force].
struct NodalConstraintForce {
  int node = 0;                      ///< node index
  Eigen::Vector2d force{0, 0};       ///< (fx, fy)
  /// The moment about z on the node's rotation (ABAQUS dof 6) [force x length],
  /// when the constraint acts on it (an *MPC BEAM's reference node).
  std::optional<double> moment;
};

/// Multiplier values owned by one constraint/contact object, for output.
struct MultiplierValues {
  std::string owner;               ///< e.g. "EQUATION 3"
  std::vector<int> nodes;          ///< node indices it acts on (for VTU field data)
  std::vector<double> value;       ///< lambda (one per multiplier)
  std::vector<double> constraint;  ///< f(u) (one per multiplier)
  /// The constraint's force on each node it acts on (one entry per node, in
  /// order of first appearance), -lambda df/du; empty when the owner does not
  /// provide it. Under penalty/augmented enforcement lambda is the force
  /// multiplier the method produces (rho f, lambda_bar + rho f).
  std::vector<NodalConstraintForce> nodal_force;
};

/// Contact state of one slave node at the end of an increment.
struct ContactNodeValues {
  int node = 0;                 ///< slave node index
  enum class Status { Open, Stick, Slip } status = Status::Open;  ///< closed frictionless: Slip
  int master_element = 0;       ///< element id of the paired master face (0: not paired)
  int master_face = 0;          ///< its face number 1..4 (S1..S4)
  /// ξ* on that face, in [-1, 1] (face_nodes() order); with SMOOTH=s, on the
  /// piece of the smoothed surface (straight remainder or corner parabola)
  /// the slave is paired with, and the face is the one that piece lies on
  /// (a corner piece: the face before the corner for ξ < 0, after it for ξ ≥ 0).
  double xi = 0;
  double gap = 0;               ///< normal gap [length], > 0 open
  double normal_force = 0;      ///< N [force], >= 0 but for the tension of CalculiX's LINEAR law at open gaps
  double pressure = 0;          ///< N / tributary area [force/area]
  double tangential_force = 0;  ///< T [force], along the master tangent, opposing the slip Δs
  double shear = 0;             ///< T / tributary area [force/area]
  double slip = 0;              ///< Δs of the increment along the master tangent [length]
  double total_slip = 0;        ///< Σ |Δs| of the slipping increments, this one included [length]
  double dissipation = 0;       ///< Σ T Δs of the slipping increments, this one included [force × length]
  Eigen::Vector2d force{0, 0};  ///< force of the master on the slave node (N n - T t) [force]
};

/// Contact output of one *CONTACT PAIR.
struct ContactPairValues {
  std::string name;
  std::vector<ContactNodeValues> nodes;
  Eigen::Vector2d total_force{0, 0};  ///< Σ force over the slave nodes (on the slave body)
  double dissipation = 0;             ///< Σ dissipation
  /// Node-based slave surface: each node's area is the one its *SURFACE data
  /// line gives (default 1), so pressure and shear are force / that area --
  /// with the default, numerically the force on the node.
  bool node_based = false;
};

/// Energies of the whole model at the end of an increment of a dynamic step
/// [energy] (totals over 2 pi for axisymmetry), ABAQUS's names. Work and
/// dissipations accumulate from the start of the first dynamic step.
struct EnergyTotals {
  double kinetic = 0;    ///< ALLKE = 1/2 v^T M v
  double strain = 0;     ///< ALLSE: stored elastic energy
  double work = 0;       ///< ALLWK: work of loads, pressures and reactions (trapezoidal in the displacements)
  double friction = 0;   ///< ALLFD: frictional dissipation of the contact pairs
  double viscous = 0;    ///< ALLVD: Rayleigh damping, C v times the displacement increments (trapezoidal)
  /// ALLPD: plastic dissipation of the elements' material points up to now
  /// (from their committed records; not in the restart file: recomputed).
  double plastic = 0;
  /// Energy the time integration removed (HHT's numerical damping, and at
  /// impacts the contact treatment): the drop of the balance since the
  /// start of the first dynamic step; negative means the scheme added energy.
  double numerical = 0;
  /// ETOTAL = ALLKE + ALLSE + ALLVD + ALLFD + ALLPD - ALLWK: constant for an
  /// exact integration.
  double total = 0;
};

/// Computes the integration-point values of one element on demand (streamed
/// results: see IncrementResults::point_source).
class ElementPointSource {
 public:
  virtual ~ElementPointSource() = default;
  /// Values at the integration points of element `element` (index into
  /// Model::elements), as IncrementResults::points[element] would hold them.
  virtual void points(int element, std::vector<PointValues>& out) const = 0;
};

/// Everything written for one converged increment.
///
/// Element values come in one of two forms. Stored (the default): `points`
/// holds every integration point of every element. Streamed
/// (AnalysisOptions::stream_element_results, what the `tether run` writers
/// use): `points` is empty, `element_stress` holds each element's mean stress
/// and `point_source` computes an element's points when asked, so the results
/// of an increment take memory per node, not per integration point. The
/// source belongs to the analysis and may be used only during
/// AnalysisObserver::on_results; a copy kept past that call must not use it.
struct IncrementResults {
  int step = 1;             ///< 1-based
  int increment = 1;        ///< 1-based within the step
  double step_time = 0;
  double total_time = 0;
  int iterations = 0;
  double increment_size = 0;  ///< step time at the increment's start is step_time - increment_size
  double period = 1;          ///< the step's time period
  /// Explicit steps: the report's span in explicit increments of the step's
  /// nominal size (period / total), (start, end]; when output is due there.
  struct ExplicitSpan {
    long start = 0, end = 0, total = 0;
  };
  std::optional<ExplicitSpan> explicit_span;
  /// Only the nodal values, the contact values and the energies: an explicit
  /// report at which no output request is due (no element values at all).
  bool energies_only = false;
  /// False when the element fields were not built: nodal_stress,
  /// nodal_strain, nodal_thermal_strain, nodal_peeq, nodal_plastic_strain,
  /// element_stress, element_peeq and the AC YIELD fields are empty (the points are still given
  /// by point_source when streamed). A streamed `*STATIC` increment builds
  /// them only when the result files are due (see files_due()); the `.dat`
  /// reads points only. The VtuWriter refuses such results.
  bool element_fields = true;
  std::vector<Eigen::Vector2d> displacement;  ///< per node
  std::vector<Eigen::Vector2d> reaction;      ///< per node: internal minus applied force at constrained dofs
                                              ///< (plus inertia and damping forces in a dynamic step)
  std::vector<Eigen::Vector2d> velocity;      ///< per node, dynamic steps only (else empty) [length/time]
  std::vector<Eigen::Vector2d> acceleration;  ///< per node, dynamic steps only (else empty) [length/time^2]
  std::vector<double> temperature;            ///< NT per node [temperature]; empty when the deck gives no temperatures
  std::optional<EnergyTotals> energy;         ///< dynamic steps only
  std::vector<Tensor4> nodal_stress;          ///< per node: average of extrapolated element values
  std::vector<Tensor4> nodal_strain;          ///< per node, as above
  /// THE per node, averaged as nodal_stress; empty when the deck gives no temperatures
  std::vector<Tensor4> nodal_thermal_strain;
  /// Plasticity (all empty / nullopt when no element keeps a material history):
  std::vector<double> nodal_peeq;             ///< per node: PEEQ averaged as nodal_stress
  std::vector<Tensor4> nodal_plastic_strain;  ///< per node: PE averaged as nodal_stress, tensor shear
  std::vector<double> element_peeq;           ///< per element: mean PEEQ of its points
  /// AC YIELD per element: the fraction of its integration points that yield
  /// (PointValues::ac_yield), in [0, 1].
  std::vector<double> element_ac_yield;
  /// AC YIELD per node: element_ac_yield averaged over the elements around
  /// the node, in [0, 1] (not extrapolated: a flag has no gradient); 1 only
  /// when every point of every element around it yields, 0 when none does.
  std::vector<double> nodal_ac_yield;
  /// SDV (all empty when no material is a user material with *DEPVAR):
  /// n_sdv = the largest NSTATV; an element with fewer (or none) counts as
  /// zeros beyond its own.
  int n_sdv = 0;
  std::vector<double> element_sdv;  ///< n_elements x n_sdv, row by element: mean over the element's points
  std::vector<double> nodal_sdv;    ///< n_nodes x n_sdv, row by node: extrapolated and averaged as nodal_stress
  std::optional<double> plastic_dissipation;  ///< ALLPD: plastic dissipation of the model up to now [energy]
  std::vector<std::vector<PointValues>> points;  ///< per element, per integration point (empty when streamed)
  std::vector<Tensor4> element_stress;        ///< streamed only: per element, mean of its point stresses
  const ElementPointSource* point_source = nullptr;  ///< streamed only: computes points[e] on demand
  std::vector<MultiplierValues> multipliers;
  std::vector<ContactPairValues> contact;     ///< one per *CONTACT PAIR
};

/// Arithmetic mean of the stresses at `points` (zero when there are none).
Tensor4 mean_stress(const std::vector<PointValues>& points);

/// Element `element`'s integration-point values: `results.points[element]`
/// when the results store them, else computed into `buffer` by
/// `results.point_source`; empty when the results have neither.
const std::vector<PointValues>& element_points(const IncrementResults& results, std::size_t element,
                                               std::vector<PointValues>& buffer);

}  // namespace tether
