#include "tether/analysis/motion_state.hpp"

namespace tether {

namespace {

constexpr int kScalars = 9;  // 7 energies, balance start, marker
constexpr int kVectors = 5;

}  // namespace

void MotionState::save(std::vector<double>& out) const {
  if (!started) return;
  for (const Eigen::VectorXd* x : {&v, &a, &static_residual, &work_force, &damping_force}) out.insert(out.end(), x->data(), x->data() + x->size());
  const EnergyTotals& e = energy;
  out.insert(out.end(), {e.kinetic, e.strain, e.work, e.friction, e.viscous, e.numerical, e.total,
                         balance_start, 1.0});
}

bool MotionState::load(std::span<const double> in, Eigen::Index n_dofs) {
  if (in.empty()) {
    started = false;
    return true;
  }
  if (in.size() != static_cast<std::size_t>(kVectors * n_dofs + kScalars) || in.back() != 1.0) return false;
  const double* p = in.data();
  for (Eigen::VectorXd* x : {&v, &a, &static_residual, &work_force, &damping_force}) {
    *x = Eigen::Map<const Eigen::VectorXd>(p, n_dofs);
    p += n_dofs;
  }
  energy = EnergyTotals{p[0], p[1], p[2], p[3], p[4], p[5], p[6]};
  balance_start = p[7];
  started = true;
  return true;
}

}  // namespace tether
