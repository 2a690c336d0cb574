#include "tether/analysis/step_system.hpp"

#include <algorithm>
#include <stdexcept>

#include "tether/analysis/amplitude.hpp"
#include "tether/analysis/constraint_checks.hpp"
#include "tether/analysis/contact_builder.hpp"
#include "tether/analysis/mortar_builder.hpp"
#include "tether/core/error.hpp"
#include "tether/solvers/condensed_solver.hpp"

namespace tether {

namespace {

/// Condensation onto the contact equations (CondensedSolver) only while the
/// dense interface system stays small (its LU costs (2/3)|I|³ per iteration)
/// and a small part of the whole.
constexpr int kMaxCondensedEquations = 3000;
constexpr int kMinCondensationRatio = 20;

/// Index of `step` in model.steps (a StepSystem is built for a step of its model).
int step_index(const Model& model, const Step& step) {
  for (std::size_t k = 0; k < model.steps.size(); ++k)
    if (&model.steps[k] == &step) return static_cast<int>(k);
  throw std::logic_error("StepSystem: the step is not one of the model's steps");
}

}  // namespace

StepSystem::StepSystem(const Discretization& discretization, const Step& step, StepLoads loads,
                       const Eigen::VectorXd& u, double total_time, const SolverSettings& settings,
                       const std::function<void(const std::string&)>& message)
    : discretization_(discretization), step_(step), settings_(settings), loads_(std::move(loads)) {
  pressures_ = discretization_.make_pressures(loads_.pressures);
  make_inertia();
  body_forces_ = std::make_unique<StepBodyForces>(discretization_, step_index(discretization_.model(), step_));
  gather_contributions();
  const std::vector<bool> prescribed = prescribed_dofs();
  if (unused_nodes_ > 0 && message)
    message(std::to_string(unused_nodes_) + " node(s) belong to no element; they get no degrees of freedom");
  EquationMap map(prescribed, discretization_.elimination_rows());
  // Cholesky (positive definite) or LDLT (multipliers) when every
  // contribution vouches for a symmetric tangent; LU otherwise.
  symmetric_ = std::all_of(contributions_.begin(), contributions_.end(),
                           [&](const Contribution* c) { return c->symmetric_tangent(step_.nlgeom); });
  if (step_.procedure == StepProcedure::ExplicitDynamic) {
    // Central differences assemble no matrix: no assembler, whose sparsity
    // pattern would cost about 0.6 kB per CPE4 element.
    explicit_equations_ = std::make_unique<EquationMap>(std::move(map));
    check_constraints(discretization_, equations(), EvaluationState{u, u, 0, total_time, 0, step_.nlgeom});
    make_solver({});
  } else {
    std::vector<int> interface = condensation_interface(map);
    // The assembler takes the list (contributions() reads it there): one
    // copy, not two; and which contributions it holds linear, before it
    // builds its pattern.
    const bool lower = lower_triangle();
    std::vector<std::uint8_t> linear = settings_.reuse_linear_bulk && bulk_linear_ ? linear_flags() : std::vector<std::uint8_t>{};
    // The inertia's tangent M / (beta dt^2) + C gamma / (beta dt) changes with the increment.
    const bool keyed = step_.procedure == StepProcedure::ImplicitDynamic;
    assembler_ = std::make_unique<Assembler>(std::move(contributions_), std::move(map), interface, lower,
                                             std::move(linear), keyed);
    contributions_ = {};
    check_constraints(discretization_, equations(), EvaluationState{u, u, 0, total_time, 0, step_.nlgeom});
    make_solver(std::move(interface));
  }

  // MUMPS here is LDLT and CHOLMOD Cholesky: both read one triangle only.
  if (!symmetric_ && (settings_.solver == SolverKind::Mumps || settings_.solver == SolverKind::Cholmod))
    throw ModelError(std::string("--solver ") +
                     (settings_.solver == SolverKind::Mumps ? "mumps (LDLT)" : "cholmod (Cholesky)") +
                     " factorizes symmetric matrices only, and this step's tangent is unsymmetric (friction, "
                     "follower pressure under NLGEOM, or a user constraint); use --solver auto or umfpack");
}

StepSystem::~StepSystem() = default;

Assembler& StepSystem::assembler() {
  if (!assembler_) throw std::logic_error("StepSystem: an explicit step has no assembler");
  return *assembler_;
}

const Assembler& StepSystem::assembler() const {
  if (!assembler_) throw std::logic_error("StepSystem: an explicit step has no assembler");
  return *assembler_;
}

const EquationMap& StepSystem::equations() const {
  return assembler_ ? assembler_->equations() : *explicit_equations_;
}

void StepSystem::apply_loads(const IncrementTimes& t, Eigen::VectorXd& u, Eigen::VectorXd& forces) {
  const Model& model = discretization_.model();
  const auto magnitude = [&](const RampedValue& v) {
    return step_magnitude(model, v.amplitude, v.start, v.target, t.step_time, t.period, t.total_time);
  };
  for (const auto& [dof, v] : loads_.prescribed) u[dof] = prescribed_value(model, v, t.step_time, t.period, t.total_time);
  equations().update_dependents(u);
  forces.setZero(discretization_.dofs().n_dofs());
  for (const auto& [dof, v] : loads_.forces) forces[dof] += magnitude(v);
  for (std::size_t k = 0; k < pressures_.size(); ++k) pressures_[k]->set_pressure(magnitude(loads_.pressure_values[k]));
  body_forces_->set_time(t.step_time, t.period, t.total_time);
}

void StepSystem::make_inertia() {
  if (step_.procedure == StepProcedure::Static) return;
  const Model& model = discretization_.model();
  const auto& elements = discretization_.elements();
  const MassKind kind = step_.dynamic.lumped_mass ? MassKind::Lumped : MassKind::Consistent;
  inertia_.reserve(elements.size());
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const int section = model.elements[e].section;
    const MaterialData* material =
        section >= 0 ? &model.materials[static_cast<std::size_t>(model.sections[static_cast<std::size_t>(section)].material)]
                     : nullptr;
    const auto damping = material && material->damping ? *material->damping : MaterialData::Damping{};
    inertia_.push_back(std::make_unique<ElementInertia>(*elements[e], kind, damping.alpha, damping.beta, newmark_));
  }
}

void StepSystem::gather_contributions() {
  const Discretization& disc = discretization_;
  std::size_t n_contact_nodes = 0;
  for (const auto& pair : disc.contact_pairs()) n_contact_nodes += 1 + pair->nodes().size();
  for (const auto& pair : disc.mortar_pairs()) n_contact_nodes += 1 + pair->nodes().size();
  contributions_.reserve(disc.elements().size() + disc.constraints().size() + disc.user_constraints().size() +
                         n_contact_nodes + pressures_.size() + inertia_.size() + body_forces_->forces().size());
  for (const auto& e : disc.elements()) contributions_.push_back(e.get());
  for (const auto& c : disc.constraints()) contributions_.push_back(c.get());
  for (const auto& c : disc.user_constraints()) contributions_.push_back(c.get());
  const auto n_bulk = contributions_.size();
  for (const auto& pair : disc.contact_pairs()) {
    contributions_.push_back(pair.get());  // searches before its nodes are evaluated
    for (Contribution* node : pair->nodes()) contributions_.push_back(node);
  }
  for (const auto& pair : disc.mortar_pairs()) {
    contributions_.push_back(pair.get());  // finds the overlaps before its nodes are evaluated
    for (Contribution* node : pair->nodes()) contributions_.push_back(node);
  }
  const auto n_contact = contributions_.size() - n_bulk;
  for (const auto& p : pressures_) contributions_.push_back(p.get()), load_contributions_.push_back(p.get());
  if (step_.procedure == StepProcedure::ImplicitDynamic)
    for (const auto& m : inertia_) contributions_.push_back(m.get());
  for (const auto& b : body_forces_->forces()) contributions_.push_back(b.get()), load_contributions_.push_back(b.get());

  const auto linear = [&](const Contribution* c) { return c->linear_in_u(step_.nlgeom); };
  const auto contact_begin = contributions_.begin() + static_cast<std::ptrdiff_t>(n_bulk);
  const auto contact_end = contact_begin + static_cast<std::ptrdiff_t>(n_contact);
  bulk_linear_ = std::all_of(contributions_.begin(), contact_begin, linear) &&
                 std::all_of(contact_end, contributions_.end(), linear);
}

std::vector<std::uint8_t> StepSystem::linear_flags() const {
  std::vector<std::uint8_t> linear(contributions_.size());
  for (std::size_t k = 0; k < contributions_.size(); ++k) linear[k] = contributions_[k]->linear_in_u(step_.nlgeom);
  return linear;
}

std::vector<bool> StepSystem::prescribed_dofs() {
  const DofMap& dofs = discretization_.dofs();
  std::vector<bool> prescribed(dofs.n_dofs(), false);
  for (const auto& [dof, value] : loads_.prescribed) prescribed[dof] = true;
  // Nodes no element or constraint uses have no dofs (as in ABAQUS): their
  // displacements are held at zero instead of making the matrix singular.
  std::vector<bool> used(dofs.n_dofs(), false);
  for (const Contribution* c : contributions_)
    for (int d : c->dofs()) used[d] = true;
  for (const auto& row : discretization_.elimination_rows())
    for (const auto& term : row.terms) used[term.first] = true;
  unused_nodes_ = 0;
  for (int node = 0; node < dofs.n_nodes(); ++node) {
    bool any = false;
    for (int c = 0; c < kDofsPerNode; ++c) any = any || used[dofs.displacement(node, c)];
    if (any) continue;
    ++unused_nodes_;
    for (int c = 0; c < kDofsPerNode; ++c) prescribed[dofs.displacement(node, c)] = true;
  }
  return prescribed;
}

std::vector<int> StepSystem::condensation_interface(const EquationMap& equations) const {
  // With contact, the Auto solver condenses onto the contact equations
  // (CondensedSolver) while they are few; the pattern then holds them all
  // to all, so that re-pairing never rebuilds it.
  // Not under NLGEOM: the bulk changes at every iteration there, and the
  // reserved block would only add fill to the ordinary factorization.
  const auto& pairs = discretization_.contact_pairs();
  const auto& mortar = discretization_.mortar_pairs();
  if (settings_.solver != SolverKind::Auto || !settings_.condense_contact || step_.nlgeom ||
      (pairs.empty() && mortar.empty()) ||
      (settings_.mortar_condensation == MortarCondensation::Sparse && !mortar.empty()))
    return {};
  std::vector<int> interface = contact_equations(pairs, discretization_.dofs(), equations);
  if (!mortar.empty()) {
    const std::vector<int> more = mortar_equations(mortar, discretization_.dofs(), equations);
    interface.insert(interface.end(), more.begin(), more.end());
    std::sort(interface.begin(), interface.end());
    interface.erase(std::unique(interface.begin(), interface.end()), interface.end());
  }
  const auto m = static_cast<int>(interface.size());
  if (!settings_.condense_any_size &&
      (m > kMaxCondensedEquations || kMinCondensationRatio * m > equations.n_equations()))
    interface.clear();
  return interface;
}

bool StepSystem::lower_triangle() const {
  // The solvers that read one triangle: CHOLMOD, MUMPS LDLT, and the
  // condensation onto the contact equations (MumpsSchur, with the dense
  // elimination of mortar multipliers, which mirrors the interface block and
  // finds each multiplier's row in the interface columns: the multipliers
  // are numbered after the displacements they couple); Auto's UMFPACK
  // fallback mirrors it. UMFPACK and SparseLU chosen by the user read both,
  // and so does the sparse mortar elimination (DualCondensedSolver): those
  // keep the whole matrix.
  const bool one_triangle = settings_.solver == SolverKind::Auto || settings_.solver == SolverKind::Mumps ||
                            settings_.solver == SolverKind::Cholmod;
  const bool sparse_mortar =
      !discretization_.mortar_pairs().empty() && settings_.mortar_condensation == MortarCondensation::Sparse;
  return symmetric_ && one_triangle && !sparse_mortar;
}

void StepSystem::make_solver(std::vector<int> interface) {
  solver_ = make_linear_solver(settings_.solver, settings_.memory_budget_mb);
  const auto& mortar = discretization_.mortar_pairs();
  if (settings_.mortar_condensation == MortarCondensation::Sparse && !mortar.empty()) {
    solver_ = std::make_unique<DualCondensedSolver>(
        mortar_dual_equations(mortar, discretization_.dofs(), equations()), std::move(solver_));
    return;
  }
  if (interface.empty()) return;
  auto c = std::make_unique<CondensedSolver>(std::move(interface), std::move(solver_), settings_.memory_budget_mb);
  if (settings_.mortar_condensation == MortarCondensation::Dense) {
    // The closed normal multipliers of mortar and node-to-segment slave nodes
    // alike, each with a displacement of its own node; an NTS node that also
    // belongs to a mortar pair stays out (contact_dual_equations).
    std::vector<DualNodeEquations> nodes = mortar_dual_equations(mortar, discretization_.dofs(), equations());
    std::vector<int> mortar_nodes;
    for (const auto& pair : mortar)
      for (const auto* faces : {&pair->setup().slave_faces, &pair->setup().master_faces})
        for (const auto& face : *faces) mortar_nodes.insert(mortar_nodes.end(), face.begin(), face.end());
    const std::vector<DualNodeEquations> nts =
        contact_dual_equations(discretization_.contact_pairs(), discretization_.dofs(), equations(), mortar_nodes);
    nodes.insert(nodes.end(), nts.begin(), nts.end());
    if (!nodes.empty()) c->eliminate_dual_multipliers(std::move(nodes));
  }
  condensed_ = c.get();
  solver_ = std::move(c);
}

}  // namespace tether
