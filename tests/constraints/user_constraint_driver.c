/* Plain-C consumer of the installed plug-in header: loads the example
 * library built against the installed tether, calls its routine on the seed's
 * equality example and checks residual and stiffness. Usage: driver LIBRARY */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <tether/constraints/user_constraint.h>

static int check(double got, double want, const char* what) {
  if (fabs(got - want) > 1e-14) {
    fprintf(stderr, "%s: got %.17g, want %.17g\n", what, got, want);
    return 1;
  }
  return 0;
}

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  void* library = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    fprintf(stderr, "%s\n", dlerror());
    return 1;
  }
  tether_user_constraint_fn routine;
  *(void**)(&routine) = dlsym(library, TETHER_USER_CONSTRAINT_DEFAULT_SYMBOL);
  if (!routine) {
    fprintf(stderr, "%s\n", dlerror());
    return 1;
  }
  const int labels[2] = {2, 5};
  const double coordinates[4] = {1, 0, 1, 0};
  const double total[4] = {0.7, -0.1, 0.2, 0.4};
  const double increment[4] = {0.1, 0.0, 0.05, 0.0};
  const double properties[2] = {1, 0.25};
  const double lambda = 3.0;
  tether_user_constraint_input in;
  memset(&in, 0, sizeof in);
  in.version = TETHER_USER_CONSTRAINT_VERSION;
  in.number = 1;
  in.need_stiffness = 1;
  in.name = "C-DRIVER";
  in.n_nodes = 2;
  in.node_labels = labels;
  in.coordinates = coordinates;
  in.dof_total = total;
  in.dof_increment = increment;
  in.n_properties = 2;
  in.properties = properties;
  in.n_multipliers = 1;
  in.multipliers = &lambda;
  double residual[5] = {0}, stiffness[25] = {0};
  char message[256] = "";
  tether_user_constraint_output out = {5, residual, stiffness, message, sizeof message};
  if (routine(&in, &out) != 0) {
    fprintf(stderr, "routine failed: %s\n", message);
    return 1;
  }
  /* r = [lambda, 0, -lambda, 0, u_a - u_b - eps lambda]; K(0,4) = K(4,0) = 1,
   * K(2,4) = K(4,2) = -1, K(4,4) = -eps; column-major. */
  const double want_r[5] = {3.0, 0, -3.0, 0, 0.5 - 0.75};
  int bad = 0;
  for (int i = 0; i < 5; ++i) bad += check(residual[i], want_r[i], "residual");
  double want_k[25] = {0};
  want_k[0 + 5 * 4] = want_k[4 + 5 * 0] = 1;
  want_k[2 + 5 * 4] = want_k[4 + 5 * 2] = -1;
  want_k[4 + 5 * 4] = -0.25;
  for (int i = 0; i < 25; ++i) bad += check(stiffness[i], want_k[i], "stiffness");
  dlclose(library);
  if (bad) return 1;
  printf("user constraint example: residual and stiffness as expected\n");
  return 0;
}
