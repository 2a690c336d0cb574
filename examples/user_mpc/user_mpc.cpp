// Two ABAQUS-style user MPCs in one routine (tether/constraints/user_mpc.h),
// picked by JTYPE, one for each form of ABAQUS's user subroutine MPC.
//
// JTYPE 1, MODE=DOF — a rigid link written as an MPC (the classic nonlinear
// ABAQUS user MPC). Node entries: a, a, b, b (node a listed twice to bring in
// both of its dofs, the ABAQUS idiom). The dependent dof is u_y of a, solved
// from the distance to b, which keeps its reference value L:
//
//   y_a = y_b + s sqrt(L^2 - (x_a - x_b)^2),   s = sign(Y_a - Y_b),
//   UE  = y_a - Y_a,
//
// JDOF = (2, 1, 1, 2): u_y(a), u_x(a), u_x(b), u_y(b). Linearising
// g = ((x_a - x_b)^2 + (y_a - y_b)^2 - L^2) / 2 = 0 at y_a = UE + Y_a:
//   A = (dy, dx, -dx, -dy),   dx = x_a - x_b, dy = y_a - y_b.
// The reference link must not be horizontal (then u_y(a) is not a function of
// the others; use u_x instead), and |x_a - x_b| < L at every call.
//
// JTYPE 2, MODE=NODE — node 1 follows node 2 rotated rigidly about node 3.
// Node entries: p (dependent), b, c. With r0 = X_p - X_c, s0 = X_b - X_c and
// s = x_b - x_c, the angle theta of the line c-b turned since the reference
// rotates r0:
//
//   x_p = x_c + R(theta) r0,   UE = x_p - X_p   (both dofs of p at once),
//   cos theta = s0.s / (|s0||s|),   sin theta = (s0 x s) / (|s0||s|).
//
// With w = d(R r0)/dtheta = (-(R r0)_y, (R r0)_x) and g = dtheta/ds =
// (-s_y, s_x) / |s|^2, the linearisation du_p - w g^T du_b - (I - w g^T) du_c = 0
// gives A(.,.,1) = I, A(.,.,2) = -w g^T, A(.,.,3) = -(I - w g^T), JDOF(.,k) = (1, 2).
// Node c is the pivot, b the point whose direction from c sets the angle; the
// distance |x_b - x_c| may change (only the direction counts).
//
// Both compute UE and A from the independent dofs only: tether's U of the
// dependent dof is its current unknown, not UE (see user_mpc.h).

#include <cmath>
#include <cstdio>

#include "tether/constraints/user_mpc.h"

namespace {

int fail(tether_user_mpc_output* out, const char* message) {
  if (out->message && out->message_capacity > 0) std::snprintf(out->message, out->message_capacity, "%s", message);
  return 1;
}

// X(i, k) and current position x(i, k) = X + U of node entry k, 1-based i, k.
double reference(const tether_user_mpc_input* in, int i, int k) { return in->x[(i - 1) + in->maxdof * (k - 1)]; }
double current(const tether_user_mpc_input* in, int i, int k) {
  return reference(in, i, k) + in->u[(i - 1) + in->maxdof * (k - 1)];
}

int rigid_link(const tether_user_mpc_input* in, tether_user_mpc_output* out) {
  if (in->mode != TETHER_USER_MPC_MODE_DOF) return fail(out, "JTYPE 1 (rigid link) needs MODE=DOF");
  if (in->n != 4 || in->node_labels[0] != in->node_labels[1] || in->node_labels[2] != in->node_labels[3])
    return fail(out, "JTYPE 1 (rigid link) needs the nodes a, a, b, b");
  const double dX = reference(in, 1, 1) - reference(in, 1, 3), dY = reference(in, 2, 1) - reference(in, 2, 3);
  const double length = std::hypot(dX, dY);
  if (dY == 0) return fail(out, "JTYPE 1: the reference link is horizontal, u_y of node a is not a function of the others");
  const double sign = dY > 0 ? 1.0 : -1.0;

  const double dx = current(in, 1, 2) - current(in, 1, 3);  // x_a (entry 2) - x_b (entry 3)
  const double dy2 = length * length - dx * dx;
  if (!(dy2 > 0)) return fail(out, "JTYPE 1: |x_a - x_b| >= L, the link cannot reach");
  const double dy = sign * std::sqrt(dy2);
  const double y_a = current(in, 2, 4) + dy;  // y_b (entry 4) + dy

  out->ue[0] = y_a - reference(in, 2, 1);
  out->jdof[0] = 2, out->a[0] = dy;   // u_y(a): the dependent dof
  out->jdof[1] = 1, out->a[1] = dx;   // u_x(a)
  out->jdof[2] = 1, out->a[2] = -dx;  // u_x(b)
  out->jdof[3] = 2, out->a[3] = -dy;  // u_y(b)
  return 0;
}

int rotate_about(const tether_user_mpc_input* in, tether_user_mpc_output* out) {
  if (in->mode != TETHER_USER_MPC_MODE_NODE) return fail(out, "JTYPE 2 (rotation about a pivot) needs MODE=NODE");
  if (in->n != 3) return fail(out, "JTYPE 2 (rotation about a pivot) needs the nodes p, b, c");
  const double r0x = reference(in, 1, 1) - reference(in, 1, 3), r0y = reference(in, 2, 1) - reference(in, 2, 3);
  const double s0x = reference(in, 1, 2) - reference(in, 1, 3), s0y = reference(in, 2, 2) - reference(in, 2, 3);
  const double sx = current(in, 1, 2) - current(in, 1, 3), sy = current(in, 2, 2) - current(in, 2, 3);
  const double s0 = std::hypot(s0x, s0y), s2 = sx * sx + sy * sy;
  if (s0 == 0 || s2 == 0) return fail(out, "JTYPE 2: nodes b and c coincide, the angle is undefined");
  const double norm = s0 * std::sqrt(s2);
  const double c = (s0x * sx + s0y * sy) / norm, s = (s0x * sy - s0y * sx) / norm;
  const double rx = c * r0x - s * r0y, ry = s * r0x + c * r0y;  // R(theta) r0
  const double w[2] = {-ry, rx}, g[2] = {-sy / s2, sx / s2};

  out->mdof = 2;
  out->ue[0] = current(in, 1, 3) + rx - reference(in, 1, 1);
  out->ue[1] = current(in, 2, 3) + ry - reference(in, 2, 1);
  for (int k = 1; k <= 3; ++k)
    for (int j = 1; j <= 2; ++j) TETHER_USER_MPC_JDOF(out, j, k) = j;
  for (int i = 1; i <= 2; ++i)
    for (int j = 1; j <= 2; ++j) {
      const double wg = w[i - 1] * g[j - 1], delta = i == j ? 1.0 : 0.0;
      TETHER_USER_MPC_A(out, i, j, 1) = delta;
      TETHER_USER_MPC_A(out, i, j, 2) = -wg;
      TETHER_USER_MPC_A(out, i, j, 3) = -(delta - wg);
    }
  return 0;
}

}  // namespace

extern "C" TETHER_USER_MPC_EXPORT int tether_user_mpc(const tether_user_mpc_input* in, tether_user_mpc_output* out) {
  if (in->version != TETHER_USER_MPC_VERSION) return fail(out, "compiled against another interface version");
  switch (in->jtype) {
    case 1: return rigid_link(in, out);
    case 2: return rotate_about(in, out);
    default: return fail(out, "unknown JTYPE (this routine has 1 = rigid link, 2 = rotation about a pivot)");
  }
}
