// Test plug-in for user_mpc_test.cpp: user MPC routines, good and bad, picked
// by JTYPE. Exported under the non-default name `test_user_mpc` only, so the
// default symbol is missing.
//
//   1: returns status 7 with a message naming the constraint;
//   2: UE = NaN;
//   3: JDOF(1) = 3 (out of range in 2D);
//   4: A(1) = 0 (zero coefficient of the dependent dof);
//   5: LMPC = 0;
//   6: DOF mode, the dependent dof switches from 1 to 2 once U(1,2) > 0.5;
//   7: NODE mode, singular A(.,.,1);
//   8: NODE mode, nonsingular non-identity A(.,.,1) = M and a known nonlinear UE
//      over nodes (p, b): UE = (u_x(b)^2, sin u_y(b)), A(.,.,1) = M,
//      A(.,.,2) = -M dUE/du_b (so the normalised gradient is [I, -dUE/du_b]);
//   9: DOF mode, linear u_x(1) = 0.5 u_x(2) - 2 u_y(2) written with A scaled by -4;
//  10: DOF mode echo: UE = TIME(1) + 100 TIME(2) + 1000 perturbed,
//      JDOF(k) = 1, A(1) = 1, A(k) = X(1,k) + 10 U(2,k) + 100 UINIT(1,k) (k > 1),
//      and it fails unless version, n, maxdof, kstep, kinc, name are as documented;
//  11: NODE mode, JDOF(2,2) = 0 but A(1,2,2) != 0.

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "tether/constraints/user_mpc.h"

namespace {

int fail(tether_user_mpc_output* out, const char* message) {
  std::snprintf(out->message, out->message_capacity, "%s", message);
  return 1;
}

}  // namespace

extern "C" TETHER_USER_MPC_EXPORT int test_user_mpc(const tether_user_mpc_input* in, tether_user_mpc_output* out) {
  const double* u = in->u;
  switch (in->jtype) {
    case 1:
      std::snprintf(out->message, out->message_capacity, "JTYPE makes no sense for %s", in->name);
      return 7;
    case 2:
      out->ue[0] = std::numeric_limits<double>::quiet_NaN();
      out->jdof[0] = 1, out->a[0] = 1;
      return 0;
    case 3: out->jdof[0] = 3, out->a[0] = 1; return 0;
    case 4: out->jdof[0] = 1, out->a[0] = 0; return 0;
    case 5: out->jdof[0] = 1, out->a[0] = 1, out->lmpc = 0; return 0;
    case 6: out->jdof[0] = u[2] > 0.5 ? 2 : 1, out->a[0] = 1; return 0;
    case 7:
      out->mdof = 2;
      for (int k = 1; k <= in->n; ++k) TETHER_USER_MPC_JDOF(out, 1, k) = 1, TETHER_USER_MPC_JDOF(out, 2, k) = 2;
      TETHER_USER_MPC_A(out, 1, 1, 1) = 1, TETHER_USER_MPC_A(out, 1, 2, 1) = 2;
      TETHER_USER_MPC_A(out, 2, 1, 1) = 2, TETHER_USER_MPC_A(out, 2, 2, 1) = 4;
      return 0;
    case 8: {
      if (in->mode != TETHER_USER_MPC_MODE_NODE || in->n != 2) return fail(out, "JTYPE 8: MODE=NODE, 2 nodes");
      const double m[2][2] = {{2.0, -1.0}, {0.5, 3.0}};
      const double bx = u[2], by = u[3];
      const double d[2][2] = {{2 * bx, 0.0}, {0.0, std::cos(by)}};  // dUE_i/du_b,j
      out->mdof = 2;
      out->ue[0] = bx * bx, out->ue[1] = std::sin(by);
      for (int k = 1; k <= 2; ++k) TETHER_USER_MPC_JDOF(out, 1, k) = 1, TETHER_USER_MPC_JDOF(out, 2, k) = 2;
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
          TETHER_USER_MPC_A(out, i + 1, j + 1, 1) = m[i][j];
          TETHER_USER_MPC_A(out, i + 1, j + 1, 2) = -(m[i][0] * d[0][j] + m[i][1] * d[1][j]);
        }
      return 0;
    }
    case 9:
      if (in->n != 3) return fail(out, "JTYPE 9: nodes 1, 2, 2");
      out->ue[0] = 0.5 * u[2] - 2 * u[5];
      out->jdof[0] = 1, out->a[0] = -4;
      out->jdof[1] = 1, out->a[1] = 2;
      out->jdof[2] = 2, out->a[2] = -8;
      return 0;
    case 10:
      if (in->version != TETHER_USER_MPC_VERSION || in->maxdof != 2 || in->n < 2 || in->kstep != 0 ||
          in->kinc != 0 || std::strcmp(in->name, "ECHO") != 0 || in->mode != TETHER_USER_MPC_MODE_DOF ||
          out->mdof != 1 || out->lmpc != 1)
        return fail(out, "JTYPE 10: inputs not as documented");
      out->ue[0] = in->time[0] + 100 * in->time[1] + 1000 * in->perturbed;
      out->jdof[0] = 1, out->a[0] = 1;
      for (int k = 1; k < in->n; ++k) {
        out->jdof[k] = 1;
        out->a[k] = in->x[2 * k] + 10 * in->u[2 * k + 1] + 100 * in->uinit[2 * k];
      }
      return 0;
    case 11:
      out->mdof = 2;
      TETHER_USER_MPC_JDOF(out, 1, 1) = 1, TETHER_USER_MPC_JDOF(out, 2, 1) = 2;
      TETHER_USER_MPC_A(out, 1, 1, 1) = 1, TETHER_USER_MPC_A(out, 2, 2, 1) = 1;
      TETHER_USER_MPC_JDOF(out, 1, 2) = 1, TETHER_USER_MPC_JDOF(out, 2, 2) = 0;
      TETHER_USER_MPC_A(out, 1, 2, 2) = 0.5;
      return 0;
    default: return fail(out, "unknown JTYPE");
  }
}
