/*
 * tether user-MPC plug-in interface (C and C++): ABAQUS's user subroutine MPC,
 * in C, for 2D solids.
 *
 * A user MPC is a routine you write, compile into a shared library and name in
 * the deck (ABAQUS: `*MPC, USER, MODE=DOF|NODE`, data line `JTYPE, nodes`):
 *
 *   *MPC, USER, MODE=DOF, LIBRARY=build/libuser_mpc.so[, SYMBOL=name]
 *   1, 10, 10, 20, 20        <- JTYPE, then the N node labels
 *
 * It has ABAQUS's two forms:
 *
 * - MODE=DOF (degree-of-freedom mode): one dependent dof, dof JDOF(1) of the
 *   first node, is given as a function of the others,
 *       u^1_JDOF(1) = UE(u^2, ..., u^N),
 *   where "node k" is the k-th entry of the node list and contributes the one
 *   dof JDOF(k). A node may be listed more than once to bring in both of its
 *   dofs (the ABAQUS idiom: `JTYPE, 1, 1, 2, 2` with JDOF = 2, 1, 1, 2 makes
 *   u_y(1) a function of u_x(1), u_x(2), u_y(2)).
 * - MODE=NODE (nodal mode): MDOF (1 or 2) dofs of the first node at once,
 *       u^1_JDOF(i,1) = UE(i)(u^2, ..., u^N),   i = 1..MDOF,
 *   node k contributing its dofs JDOF(1..MDOF, k).
 *
 * The routine returns the value(s) UE and the coefficients A of the
 * linearised constraint, exactly as in ABAQUS:
 *
 *   DOF:   sum_k A(k) du^k_JDOF(k) = 0                          (k = 1..N)
 *   NODE:  sum_k sum_j A(i,j,k) du^k_JDOF(j,k) = 0, i = 1..MDOF (j = 1..MDOF)
 *
 * with A(1) (DOF) or the block A(.,.,1) (NODE) multiplying the dependent dofs.
 * In other words A(k)/A(1) = -dUE/du^k_JDOF(k), and in NODE mode
 * A(.,.,1)^-1 A(.,j,k) = -dUE/du^k_JDOF(j,k). Any nonzero scaling of A (of the
 * equations, NODE mode: any nonsingular A(.,.,1)) is allowed.
 *
 * How tether uses it. tether does not eliminate the dependent dof; it enforces
 * the constraint equations
 *
 *   DOF:   f   = u^1_JDOF(1)   - UE     = 0   (1 equation)
 *   NODE:  f_i = u^1_JDOF(i,1) - UE(i)  = 0   (MDOF equations)
 *
 * with Lagrange multipliers (or penalty, augmented Lagrangian) like any other
 * tether constraint. Their gradient is A normalised so that df/du_dependent = 1
 * (DOF: df/du^k_JDOF(k) = A(k)/A(1); NODE: the rows of A(.,.,1)^-1 A). The
 * interface gives no second derivatives, so tether differentiates the
 * normalised A numerically (central differences) for the Hessian of f. That
 * is the one place tether differentiates numerically; see
 * tether/constraints/user_mpc_constraint.hpp.
 *
 * Consequences for the routine:
 * - Compute UE and A from the independent dofs only. tether's current iterate
 *   need not satisfy the constraint yet (the dependent dof is an unknown of
 *   its own, not eliminated), so U of the dependent dof(s) is NOT UE: ignore
 *   it, and evaluate A where the dependent dof equals UE. Then A is the exact
 *   derivative of UE and Newton converges quadratically.
 * - The dependent dofs (JDOF(1) / JDOF(.,1)) and, in NODE mode, MDOF must not
 *   change between calls. tether calls the routine once in the reference
 *   configuration (U = UINIT = 0, times 0) when the constraint is built, to
 *   learn them, and reports an error if a later call changes them.
 * - LMPC = 0 (ABAQUS: switch the constraint off) is not supported: the
 *   multiplier unknowns of a constraint cannot disappear during a step.
 *   tether reports it as an error.
 * - 2D only: dofs are 1 (x) and 2 (y); MAXDOF = 2. There are no rotations,
 *   temperatures or field variables, and no transformed (LTRAN/TRAN) dofs:
 *   U, UINIT and X are in the global system.
 *
 * Array layout. Fortran arrays become flat C arrays in column-major order
 * (first index fastest) with the leading dimension MAXDOF = 2 fixed, so they
 * can be indexed the same way in both modes (0-based indices in C):
 *
 *   X(i,k), U(i,k), UINIT(i,k)       -> x[i + 2*k], u[i + 2*k], uinit[i + 2*k]
 *   DOF:  A(k), JDOF(k)              -> a[k], jdof[k]
 *   NODE: A(i,j,k)                   -> a[i + 2*j + 4*k]
 *         JDOF(j,k)                  -> jdof[j + 2*k]
 *         UE(i)                      -> ue[i]
 *
 * (i, j = 0..MDOF-1, k = 0..N-1; with MDOF = 1 the entries with i or j = 1 are
 * unused). The TETHER_USER_MPC_A and TETHER_USER_MPC_JDOF macros below do
 * this indexing.
 *
 * Return 0 on success. A nonzero status (with an explanation in `message`),
 * NaN or infinite outputs, a dof number out of range, a zero A(1) or a
 * singular A(.,.,1) make tether report an error naming the constraint; during
 * an analysis Newton then cuts the increment back.
 *
 * The routine must be reentrant: tether may call it concurrently for
 * different constraints (OpenMP assembly), and calls it 4*M + 1 times per
 * tangent evaluation for the numerical Hessian (M = number of distinct nodes). Do not keep writable global
 * state without locking, and do not let C++ exceptions escape it.
 */
#ifndef TETHER_CONSTRAINTS_USER_MPC_H
#define TETHER_CONSTRAINTS_USER_MPC_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Version of this interface; tether puts it in tether_user_mpc_input.version. A
 * routine may refuse (return nonzero) when it differs from the version it was
 * compiled against. Changes that move or remove fields increase it. */
#define TETHER_USER_MPC_VERSION 1

/* Symbol tether looks up when the deck gives no SYMBOL= parameter. */
#define TETHER_USER_MPC_DEFAULT_SYMBOL "tether_user_mpc"

/* MAXDOF: displacement dofs per node (2D solids: 1 = x, 2 = y; axisymmetric: r, z). */
#define TETHER_USER_MPC_MAXDOF 2

/* Values of tether_user_mpc_input.mode (the deck's MODE= parameter). */
#define TETHER_USER_MPC_MODE_DOF 0  /* MODE=DOF: one dependent dof per call (ABAQUS's default) */
#define TETHER_USER_MPC_MODE_NODE 1 /* MODE=NODE: MDOF dependent dofs of the first node */

/* NODE mode: A(i,j,k) and JDOF(j,k) of ABAQUS with 1-based i, j, k, as lvalues. */
#define TETHER_USER_MPC_A(out, i, j, k) \
  ((out)->a[((i)-1) + TETHER_USER_MPC_MAXDOF * ((j)-1) + TETHER_USER_MPC_MAXDOF * TETHER_USER_MPC_MAXDOF * ((k)-1)])
#define TETHER_USER_MPC_JDOF(out, j, k) ((out)->jdof[((j)-1) + TETHER_USER_MPC_MAXDOF * ((k)-1)])

/* Marks the routine as exported from the shared library. */
#if defined(_WIN32)
#define TETHER_USER_MPC_EXPORT __declspec(dllexport)
#elif defined(__GNUC__) || defined(__clang__)
#define TETHER_USER_MPC_EXPORT __attribute__((visibility("default")))
#else
#define TETHER_USER_MPC_EXPORT
#endif

/* What tether passes in (ABAQUS's input arguments). All arrays are owned by
 * tether and valid only during the call. Lengths are in the deck's length
 * unit, times in its time unit. */
typedef struct tether_user_mpc_input {
  int version;  /* TETHER_USER_MPC_VERSION of the calling tether */
  int mode;     /* TETHER_USER_MPC_MODE_DOF or TETHER_USER_MPC_MODE_NODE (MODE= in the deck) */
  int jtype;    /* JTYPE: the user integer from the data line, e.g. to pick one of several
                   constraint types implemented by one routine */
  int n;        /* N: number of node entries of the constraint (>= 1), in deck order;
                   a node listed twice is two entries */
  int maxdof;   /* MAXDOF = TETHER_USER_MPC_MAXDOF = 2: leading dimension of x, u, uinit */
  const int* node_labels; /* [n] user node labels as in the deck */
  const double* x;        /* X(2,N): [2*n] reference coordinates, x[i + 2*k] = coordinate
                             i+1 of node entry k [length]. (ABAQUS: X(6,N).) */
  const double* u;        /* U(MAXDOF,N): [2*n] total displacements at the current iterate,
                             u[i + 2*k] [length]. For the dependent dof(s) this is tether's
                             current unknown, not UE: do not use it. */
  const double* uinit;    /* UINIT(MAXDOF,N): [2*n] total displacements at the start of the
                             current increment (the last converged state) [length] */
  int kstep;    /* KSTEP: step number (1-based); 0 when not known to tether, which is the
                   case for all calls at present (tether's constraint interface passes
                   times only) and for the reference call when the constraint is built */
  int kinc;     /* KINC: increment number within the step; 0 when not known (see kstep) */
  double time[2]; /* TIME(1): step time, TIME(2): total time, both at the end of the
                     current increment [time]; 0 in the reference call */
  const char* name; /* constraint name for messages (NAME= or generated), NUL-terminated */
  int perturbed;  /* 0: the evaluation at tether's current iterate (or the reference call);
                     1: a call at a perturbed state that tether makes to difference A
                     numerically. The outputs must be computed the same way; the flag only
                     lets a routine keep diagnostics quiet. */
} tether_user_mpc_input;

/* What the routine fills (ABAQUS's output arguments). tether allocates and
 * zeroes everything before every call and presets mdof and lmpc. */
typedef struct tether_user_mpc_output {
  int mdof;       /* number of dependent dofs of the first node. DOF mode: tether sets 1;
                     leave it. NODE mode: tether presets MAXDOF = 2; set 1 to eliminate
                     a single dof of the first node. (ABAQUS NODE mode: the number of
                     dependent dofs, given by JDOF(.,1).) */
  int lmpc;       /* LMPC: tether presets 1. ABAQUS's LMPC = 0 (deactivate the constraint)
                     is not supported and reported as an error. */
  double ue[TETHER_USER_MPC_MAXDOF]; /* UE: DOF mode: ue[0] = total value the dependent dof
                     u^1_JDOF(1) must take. NODE mode: ue[i] = total value of dependent dof
                     u^1_JDOF(i+1,1), i < MDOF [length] */
  double* a;      /* A: [MAXDOF*MAXDOF*n] coefficients of the linearised constraint.
                     DOF mode: a[k] = A(k+1), k < n; a[0] = A(1) multiplies the dependent
                     dof and must be nonzero.
                     NODE mode: a[i + 2*j + 4*k] = A(i+1,j+1,k+1), the coefficient in
                     equation i of dof JDOF(j+1,k+1) of node entry k; the block k = 0
                     (the dependent dofs) must be nonsingular. */
  int* jdof;      /* JDOF: [MAXDOF*n] dof numbers (1 = x, 2 = y).
                     DOF mode: jdof[k] = JDOF(k+1): the dof of node entry k that A(k+1)
                     multiplies; jdof[0] is the dependent dof (1 or 2). For k > 0, 0
                     means "no term" and then A(k+1) must be 0.
                     NODE mode: jdof[j + 2*k] = JDOF(j+1,k+1), j < MDOF; jdof[j] (k = 0)
                     are the dependent dofs, distinct, each 1 or 2; for k > 0, 0 means
                     "no term" and then A(.,j+1,k+1) must be 0. */
  char* message;             /* buffer for a NUL-terminated explanation when returning
                                nonzero; tether prints it with the constraint's name */
  size_t message_capacity;   /* size of message in bytes, including the terminating NUL */
} tether_user_mpc_output;

/* A user-MPC routine: returns 0 on success, nonzero on failure (see above). */
typedef int (*tether_user_mpc_fn)(const tether_user_mpc_input* in, tether_user_mpc_output* out);

/* The routine under the default symbol name. Define it (with C linkage) in your
 * library, or define a function of type tether_user_mpc_fn under another name
 * and give that name with SYMBOL= in the deck. One routine serves both modes
 * (test in->mode) and any number of JTYPEs. */
TETHER_USER_MPC_EXPORT int tether_user_mpc(const tether_user_mpc_input* in, tether_user_mpc_output* out);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* TETHER_CONSTRAINTS_USER_MPC_H */
