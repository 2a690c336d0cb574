// Test plug-in for user_constraint_test.cpp: misbehaving user routines.
//   properties[0] = 1: returns status 7 with a message;
//   properties[0] = 2: returns NaN in the residual;
//   properties[0] = 3: returns Inf in the stiffness (only when asked for it).
// Exported under a non-default name only, so the default symbol is missing.

#include <cmath>
#include <cstdio>
#include <limits>

#include "tether/constraints/user_constraint.h"

extern "C" TETHER_USER_CONSTRAINT_EXPORT int misbehaving_constraint(const tether_user_constraint_input* in,
                                                                    tether_user_constraint_output* out) {
  const int mode = in->n_properties > 0 ? static_cast<int>(in->properties[0]) : 0;
  switch (mode) {
    case 1:
      std::snprintf(out->message, out->message_capacity, "properties make no sense for %s", in->name);
      return 7;
    case 2: out->residual[0] = std::numeric_limits<double>::quiet_NaN(); return 0;
    case 3:
      if (in->need_stiffness) out->stiffness[out->n * out->n - 1] = std::numeric_limits<double>::infinity();
      return 0;
    default: return 0;
  }
}

// Echoes its inputs into the stiffness so a test can check what tether passes
// (needs n >= 5): column 0 = coordinates, 1 = dof_total, 2 = dof_increment,
// 3 = [number, flag, need_stiffness, label 0, label 1], 4 = [step_time,
// total_time, dt, version, n_properties]; residual = properties then multipliers.
extern "C" TETHER_USER_CONSTRAINT_EXPORT int echo_constraint(const tether_user_constraint_input* in,
                                                             tether_user_constraint_output* out) {
  const int n = out->n, nu = TETHER_USER_CONSTRAINT_DOFS_PER_NODE * in->n_nodes;
  if (n < 5 || in->n_nodes < 2) return 1;
  for (int i = 0; i < nu; ++i) {
    out->stiffness[i + n * 0] = in->coordinates[i];
    out->stiffness[i + n * 1] = in->dof_total[i];
    out->stiffness[i + n * 2] = in->dof_increment[i];
  }
  const double ints[5] = {double(in->number), double(in->flag), double(in->need_stiffness),
                          double(in->node_labels[0]), double(in->node_labels[1])};
  const double reals[5] = {in->step_time, in->total_time, in->dt, double(in->version), double(in->n_properties)};
  for (int i = 0; i < 5; ++i) out->stiffness[i + n * 3] = ints[i], out->stiffness[i + n * 4] = reals[i];
  int row = 0;
  for (int p = 0; p < in->n_properties && row < n; ++p) out->residual[row++] = in->properties[p];
  for (int k = 0; k < in->n_multipliers && row < n; ++k) out->residual[row++] = in->multipliers[k];
  return 0;
}
