// The seed's simplest user constraint (EN234FEA `user_constraint`, "simple
// equality"): displacement component i of node a equals that of node b,
//
//   f = u_i^a - u_i^b = 0,   enforced as   f - eps * lambda = 0.
//
// Properties: [0] the component i (1 = x, 2 = y, as in the deck),
//             [1] the compliance eps >= 0 (optional, default 0) [length/force].
// Nodes: exactly 2 (a, b). Multipliers: exactly 1.
//
// In tether's sign convention (user_constraint.h), with unknowns
// d = [u_x^a, u_y^a, u_x^b, u_y^b, lambda]:
//   r = [ lambda e_i ; -lambda e_i ; u_i^a - u_i^b - eps lambda ]
//   K = [ 0     0     e_i ]
//       [ 0     0    -e_i ]
//       [ e_i^T -e_i^T -eps ]
// EN234FEA's listing stores the negative residual; otherwise it is the same.

#include <cstdio>

#include "tether/constraints/user_constraint.h"

namespace {

int fail(tether_user_constraint_output* out, const char* message) {
  if (out->message && out->message_capacity > 0) std::snprintf(out->message, out->message_capacity, "%s", message);
  return 1;
}

}  // namespace

extern "C" TETHER_USER_CONSTRAINT_EXPORT int tether_user_constraint(const tether_user_constraint_input* in,
                                                                    tether_user_constraint_output* out) {
  if (in->version != TETHER_USER_CONSTRAINT_VERSION) return fail(out, "compiled against another interface version");
  if (in->n_nodes != 2 || in->n_multipliers != 1)
    return fail(out, "equal_displacement needs exactly 2 nodes and 1 multiplier");
  if (in->n_properties < 1 || in->n_properties > 2)
    return fail(out, "equal_displacement needs properties: component (1 or 2)[, compliance]");
  const int component = static_cast<int>(in->properties[0]);
  if ((component != 1 && component != 2) || in->properties[0] != component)
    return fail(out, "equal_displacement: property 1 (component) must be 1 or 2");
  const double eps = in->n_properties > 1 ? in->properties[1] : 0.0;
  if (eps < 0) return fail(out, "equal_displacement: property 2 (compliance) must be >= 0");

  const int per_node = TETHER_USER_CONSTRAINT_DOFS_PER_NODE;
  const int n = out->n;              // 5 = 2 nodes x 2 dofs + 1 multiplier
  const int a = component - 1;       // row of u_i of node a
  const int b = per_node + a;        // row of u_i of node b
  const int l = 2 * per_node;        // row of the multiplier
  const double lambda = in->multipliers[0];

  // Residual (tether zeroes both arrays before the call).
  out->residual[a] = lambda;
  out->residual[b] = -lambda;
  out->residual[l] = in->dof_total[a] - in->dof_total[b] - eps * lambda;

  // Stiffness, column-major: K(i, j) = stiffness[i + n * j].
  auto k = [&](int i, int j) -> double& { return out->stiffness[i + n * j]; };
  k(a, l) = 1.0;
  k(l, a) = 1.0;
  k(b, l) = -1.0;
  k(l, b) = -1.0;
  k(l, l) = -eps;
  return 0;
}
