/* Velocity Verlet (kick-drift-kick) for particles and density, and the
 * time-step limits of every enabled module (the stability report). */
#ifndef DMHS_INTEGRATE_H
#define DMHS_INTEGRATE_H
#include <petscsys.h>

struct sim;

#define DT_LIMITS_MAX 32
typedef struct dt_limit {
  char name[32];    /* e.g. "sph sound speed" */
  char formula[96]; /* what was evaluated, naming the length it uses */
  double value;     /* [s] */
  PetscBool inner;  /* from a solid_internal module: bounds the solid sub-step */
} dt_limit;

typedef struct dt_limits {
  int n;
  dt_limit item[DT_LIMITS_MAX];
} dt_limits;

PetscErrorCode dt_limits_add(dt_limits *l, const char *name, const char *formula, double value);
/* Smallest limit and its index, or +inf / -1 when there is none. */
double dt_limits_min(const dt_limits *l, int *which);

/* First kick and drift: v += dt/2 a, x += dt v, rho += dt/2 drho; predicted v_est. */
PetscErrorCode integrate_first_half(struct sim *s);
/* Second kick: v += dt/2 a, rho += dt/2 drho. */
PetscErrorCode integrate_second_half(struct sim *s);
/* Prints every limit beside dt; stops or warns (per -preflight) when dt exceeds one
 * or the kernel support holds too few neighbours at rest spacing. */

/* Stops the run at the first non-finite value (position, velocity, density,
 * pressure, acceleration, density rate) or a particle outside the box. */
PetscErrorCode integrate_check_state(struct sim *s);
/* integrate_second_half, then integrate_check_state, in two passes over the rows instead of
 * three when SPH's fields exist (the step loop's): the same results and the same stop. */
PetscErrorCode integrate_second_half_checked(struct sim *s);

#endif
