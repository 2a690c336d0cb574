#include "tether/constraints/user_constraint_element.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "tether/core/error.hpp"
#include "tether/dofs/dof_map.hpp"

namespace tether {

namespace {

/// The routine's arrays hold node a's components at [kAbiDofs * a + c], in the
/// order of its node list (user_constraint.h); the global numbering is DofMap's.
constexpr int kAbiDofs = TETHER_USER_CONSTRAINT_DOFS_PER_NODE;
static_assert(kAbiDofs == kDofsPerNode, "user constraint dofs per node must match the DofMap");

/// Position of component `c` of the constraint's node `a` in the routine's arrays.
constexpr int abi_index(int a, int c) { return kAbiDofs * a + c; }
/// The constraint's node (0-based position in its list) of displacement row `i` of the routine's arrays.
constexpr int abi_node(int i) { return i / kAbiDofs; }
/// The component (0: x, 1: y) of displacement row `i` of the routine's arrays.
constexpr int abi_component(int i) { return i % kAbiDofs; }

}  // namespace

UserConstraintElement::UserConstraintElement(std::string library_path, std::string symbol, int number,
                                             std::vector<int> node_indices, std::vector<int> node_labels,
                                             std::vector<Eigen::Vector2d> reference, std::vector<double> properties,
                                             int n_multipliers, int first_multiplier, const DofMap& dofs,
                                             std::string name, int flag)
    : symbol_(symbol.empty() ? std::string(TETHER_USER_CONSTRAINT_DEFAULT_SYMBOL) : std::move(symbol)),
      number_(number),
      flag_(flag),
      node_indices_(std::move(node_indices)),
      node_labels_(std::move(node_labels)),
      properties_(std::move(properties)),
      m_(n_multipliers),
      name_(std::move(name)) {
  const auto nn = node_indices_.size();
  if (nn == 0 || node_labels_.size() != nn || reference.size() != nn)
    throw std::invalid_argument(name_ + ": user constraint needs >= 1 node and one label and coordinate pair per node");
  if (m_ < 0) throw std::invalid_argument(name_ + ": negative number of multipliers");
  if (m_ > 0 && (!dofs.is_multiplier(first_multiplier) || first_multiplier + m_ > dofs.n_dofs()))
    throw std::invalid_argument(name_ + ": multipliers " + std::to_string(first_multiplier) + "+" +
                                std::to_string(m_) + " were not reserved with DofMap::add_multipliers");
  for (std::size_t a = 0; a < nn; ++a) {
    const int node = node_indices_[a];
    if (node < 0 || node >= dofs.n_nodes())
      throw std::invalid_argument(name_ + ": node index " + std::to_string(node) + " out of range");
    coordinates_.push_back(reference[a].x());
    coordinates_.push_back(reference[a].y());
    for (int c = 0; c < kAbiDofs; ++c) dofs_.push_back(dofs.displacement(node, c));
  }
  for (int k = 0; k < m_; ++k) dofs_.push_back(first_multiplier + k);

  try {
    library_ = SharedLibrary::open(library_path);
  } catch (const ModelError& e) {
    throw ModelError("user constraint " + name_ + ": " + e.what() + " (looking for routine '" + symbol_ + "')");
  }
  std::string error;
  void* address = library_->symbol(symbol_, error);
  if (!address)
    throw ModelError("user constraint " + name_ + ": shared library '" + library_path + "' has no routine '" +
                     symbol_ + "': " + error +
                     " (define it with C linkage, extern \"C\", and export it, or name it with SYMBOL=)");
  routine_ = reinterpret_cast<tether_user_constraint_fn>(address);
}

std::string UserConstraintElement::who() const {
  return "user constraint " + name_ + " (routine '" + symbol_ + "' in '" + library_->path() + "')";
}

void UserConstraintElement::call(const EvaluationState& state, Eigen::VectorXd& residual,
                                 Eigen::MatrixXd* tangent) const {
  const int nu = abi_index(n_nodes(), 0);
  const int n = nu + m_;
  std::vector<double> total(nu), increment(nu), lambda(m_);
  for (int i = 0; i < nu; ++i) {
    total[i] = state.u[dofs_[i]];
    increment[i] = total[i] - state.u_start[dofs_[i]];
  }
  for (int k = 0; k < m_; ++k) lambda[k] = state.u[dofs_[nu + k]];

  tether_user_constraint_input in{};
  in.version = TETHER_USER_CONSTRAINT_VERSION;
  in.number = number_;
  in.flag = flag_;
  in.need_stiffness = tangent ? 1 : 0;
  in.name = name_.c_str();
  in.n_nodes = n_nodes();
  in.node_labels = node_labels_.data();
  in.coordinates = coordinates_.data();
  in.dof_total = total.data();
  in.dof_increment = increment.data();
  in.n_properties = static_cast<int>(properties_.size());
  in.properties = properties_.empty() ? nullptr : properties_.data();
  in.n_multipliers = m_;
  in.multipliers = m_ > 0 ? lambda.data() : nullptr;
  in.step_time = state.step_time;
  in.total_time = state.total_time;
  in.dt = state.dt;

  residual.setZero(n);
  Eigen::MatrixXd scratch;
  Eigen::MatrixXd& stiffness = tangent ? *tangent : scratch;
  stiffness.setZero(n, n);  // column-major, as the interface promises
  RoutineMessage message{};

  tether_user_constraint_output out{};
  out.n = n;
  out.residual = residual.data();
  out.stiffness = stiffness.data();
  out.message = message.data();
  out.message_capacity = message.size();

  const int status = routine_(&in, &out);
  check_routine_status(status, message, who());

  auto describe_row = [&](int i) {
    if (i < nu)
      return "node " + std::to_string(node_labels_[static_cast<std::size_t>(abi_node(i))]) + " dof " +
             std::to_string(abi_component(i) + 1);
    return "multiplier " + std::to_string(i - nu + 1);
  };
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(residual[i]))
      throw ModelError(who() + " returned a non-finite residual (" + std::to_string(residual[i]) + ") at row " +
                       std::to_string(i) + " (" + describe_row(i) + ")");
  if (!tangent) return;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (!std::isfinite(stiffness(i, j)))
        throw ModelError(who() + " returned a non-finite stiffness (" + std::to_string(stiffness(i, j)) +
                         ") at row " + std::to_string(i) + " (" + describe_row(i) + "), column " + std::to_string(j) +
                         " (" + describe_row(j) + ")");
}

void UserConstraintElement::evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const {
  call(state, out.residual, need_tangent ? &out.tangent : nullptr);
}

MultiplierValues UserConstraintElement::values(const EvaluationState& state) const {
  Eigen::VectorXd residual;
  call(state, residual, nullptr);
  const int nu = abi_index(n_nodes(), 0);
  MultiplierValues v;
  v.owner = name_;
  v.nodes = node_indices_;
  v.value.resize(m_);
  v.constraint.resize(m_);
  for (int k = 0; k < m_; ++k) {
    v.value[k] = state.u[dofs_[nu + k]];
    v.constraint[k] = residual[nu + k];
  }
  // The force the constraint exerts on a displacement dof is -residual (user_constraint.h).
  for (int a = 0; a < n_nodes(); ++a)
    v.nodal_force.push_back(
        {node_indices_[a], -Eigen::Vector2d(residual[abi_index(a, 0)], residual[abi_index(a, 1)]), std::nullopt});
  return v;
}

}  // namespace tether
