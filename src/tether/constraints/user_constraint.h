/*
 * tether user-constraint plug-in interface (C and C++).
 *
 * A user constraint is a function you write, compile into a shared library
 * and name in the deck:
 *
 *   *CONSTRAINT, TYPE=USER, LIBRARY=build/libmy_constraint.so, NODES=2, NAME=TIE-1
 *   2, 5               <- node labels (NODES of them)
 *   1, 0.0             <- properties (any number of lines)
 *
 * tether calls the function at every Newton iteration with the constraint's
 * nodes, coordinates, displacements and current multipliers (the inputs of
 * EN234FEA's `user_constraint`) and it returns the residual and stiffness over
 * the constraint's unknowns. It is the C analogue of tether's built-in
 * Lagrange-multiplier element (tether/constraints/constraint_element.hpp).
 *
 * Unknowns of a constraint ("element dofs"), n = 2*n_nodes + n_multipliers:
 *
 *   d = [ u_x(node 0), u_y(node 0), u_x(node 1), u_y(node 1), ...,
 *         lambda_0, ..., lambda_{m-1} ]
 *
 * Sign convention (the same as every tether element; residual = out-of-balance
 * force, Newton solves K dd = -r). For m constraint equations f_k(u) = 0
 * enforced with multipliers lambda_k and an optional regularisation
 * f_k - eps * lambda_k = 0:
 *
 *   residual[i]           = sum_k lambda_k * df_k/du_i   (i < 2*n_nodes)  [force]
 *   residual[2*n_nodes+k] = f_k(u) - eps * lambda_k                        [units of f]
 *   stiffness(i, j)       = d residual[i] / d d_j, i.e.
 *       K = [ sum_k lambda_k d2f_k/du2    df/du^T ]
 *           [ df/du                       -eps I  ]
 *
 * The force the constraint exerts on displacement dof i is -residual[i].
 * Compared with EN234FEA's `user_constraint`, tether's residual is the
 * negative of `constraint_residual`; write f - eps*lambda (not f + eps*lambda)
 * in the multiplier rows, so that eps > 0 is a compliance (a spring 1/eps).
 * You are not limited to this form: any residual whose stiffness is its exact
 * derivative works (n_multipliers = 0 gives a penalty constraint, for
 * example), but Newton converges quadratically only if the stiffness is the
 * exact derivative of the residual.
 *
 * The function must be reentrant: tether may call it concurrently from several
 * threads for different constraints (OpenMP assembly). Do not keep writable
 * global state without locking, and do not let C++ exceptions escape it
 * (return a nonzero status instead).
 */
#ifndef TETHER_CONSTRAINTS_USER_CONSTRAINT_H
#define TETHER_CONSTRAINTS_USER_CONSTRAINT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Version of this interface; tether puts it in tether_user_constraint_input.version.
 * A routine may refuse (return nonzero) when it differs from the version it was
 * compiled against. Changes that move or remove fields increase it. */
#define TETHER_USER_CONSTRAINT_VERSION 1

/* Symbol tether looks up when the deck gives no SYMBOL= parameter. */
#define TETHER_USER_CONSTRAINT_DEFAULT_SYMBOL "tether_user_constraint"

/* Displacement components per node (2D solids: x, y; axisymmetric: r, z). */
#define TETHER_USER_CONSTRAINT_DOFS_PER_NODE 2

/* Marks the routine as exported from the shared library. */
#if defined(_WIN32)
#define TETHER_USER_CONSTRAINT_EXPORT __declspec(dllexport)
#elif defined(__GNUC__) || defined(__clang__)
#define TETHER_USER_CONSTRAINT_EXPORT __attribute__((visibility("default")))
#else
#define TETHER_USER_CONSTRAINT_EXPORT
#endif

/* What tether passes in. All arrays are owned by tether and valid only during
 * the call. "Node k" is the k-th node of the constraint, 0-based, in the order
 * given in the deck. Lengths are in the deck's length unit, forces in its force
 * unit, times in its time unit. */
typedef struct tether_user_constraint_input {
  int version;          /* TETHER_USER_CONSTRAINT_VERSION of the calling tether */
  int number;           /* constraint number: 1-based position among the model's constraints */
  int flag;             /* user integer from the deck (FLAG=, default 0), e.g. to pick a
                           constraint type when one routine implements several */
  int need_stiffness;   /* 1: fill stiffness; 0: only the residual is used (the routine
                           may still fill stiffness) */
  const char* name;     /* constraint name from the deck (NAME=), NUL-terminated */

  int n_nodes;               /* number of nodes of the constraint, >= 1 */
  const int* node_labels;    /* [n_nodes] user node labels as in the deck */
  const double* coordinates; /* [2*n_nodes] reference coordinates x0,y0, x1,y1, ... [length] */
  const double* dof_total;   /* [2*n_nodes] total displacement at the current Newton iterate:
                                u_x(node 0), u_y(node 0), u_x(node 1), ... [length].
                                (EN234FEA's dof_total + dof_increment.) */
  const double* dof_increment; /* [2*n_nodes] displacement increment since the start of the
                                  current load increment, same layout [length].
                                  dof_total - dof_increment = converged start values. */

  int n_properties;          /* number of properties, >= 0 */
  const double* properties;  /* [n_properties] property list in deck order (user units);
                                NULL when n_properties == 0 */

  int n_multipliers;         /* m: number of Lagrange multipliers of the constraint, >= 0 */
  const double* multipliers; /* [m] current multiplier values lambda_k, the generalised
                                force of equation k [force * length / units of f; a force
                                when f is a length]; NULL if m == 0 */

  double step_time;   /* time within the step at the end of the increment [time] */
  double total_time;  /* total time at the end of the increment [time] */
  double dt;          /* size of the current increment [time] */
} tether_user_constraint_input;

/* What the routine fills. tether allocates the arrays and zeroes them before
 * every call, so only the nonzero entries need be written. */
typedef struct tether_user_constraint_output {
  int n;              /* n = 2*n_nodes + n_multipliers: length of residual, order of stiffness */
  double* residual;   /* [n] residual over d (see the sign convention above):
                         rows 0..2*n_nodes-1: sum_k lambda_k df_k/du_i [force];
                         rows 2*n_nodes+k:    f_k - eps*lambda_k [units of f] */
  double* stiffness;  /* [n*n] column-major: stiffness[i + n*j] = d residual[i] / d d_j
                         (the same layout as a Fortran array K(n,n), K(ROW,COLUMN)) */
  char* message;             /* buffer for a NUL-terminated explanation when returning nonzero;
                                tether prints it with the constraint's name */
  size_t message_capacity;   /* size of message in bytes, including the terminating NUL */
} tether_user_constraint_output;

/* A user-constraint routine: returns 0 on success; nonzero reports a failure
 * (invalid properties, a configuration the constraint cannot handle, ...).
 * tether then treats the Newton attempt as failed and cuts the increment back,
 * printing `message`. NaN or infinite outputs are treated the same way. */
typedef int (*tether_user_constraint_fn)(const tether_user_constraint_input* in,
                                         tether_user_constraint_output* out);

/* The routine under the default symbol name. Define it (with C linkage) in your
 * library, or define a function of type tether_user_constraint_fn under another
 * name and give that name with SYMBOL= in the deck. */
TETHER_USER_CONSTRAINT_EXPORT int tether_user_constraint(const tether_user_constraint_input* in,
                                                         tether_user_constraint_output* out);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* TETHER_CONSTRAINTS_USER_CONSTRAINT_H */
