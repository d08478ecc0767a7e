/* Velocity Verlet (kick-drift-kick) for particles and density, and the state check
 * after every step. */
#ifndef DMHS_INTEGRATE_H
#define DMHS_INTEGRATE_H
#include <petscsys.h>

struct sim;

/* First kick and drift: v += dt/2 a, x += dt v, rho += dt/2 drho; predicted v_est. */
PetscErrorCode integrate_first_half(struct sim *s);
/* Second kick: v += dt/2 a, rho += dt/2 drho. */
PetscErrorCode integrate_second_half(struct sim *s);
/* Stops the run at the first non-finite value (position, velocity, density,
 * pressure, acceleration, density rate) or a particle outside the box. */
PetscErrorCode integrate_check_state(struct sim *s);
/* integrate_second_half, then integrate_check_state, in two passes over the rows instead of
 * three when SPH's fields exist (the step loop's): the same results and the same stop. */
PetscErrorCode integrate_second_half_checked(struct sim *s);

#endif
