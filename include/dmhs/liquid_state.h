/* The weakly compressible bounds of the liquid: the largest density
 * deviation and the largest Mach number over the fluid particles, the two
 * figures every liquid scene reports (a run is credible while they stay
 * within a few percent and below 0.1). */
#ifndef DMHS_LIQUID_STATE_H
#define DMHS_LIQUID_STATE_H
#include "dmhs/sim.h"

/* Over all ranks: max |rho/rho0 - 1| and max |v|/c0 of the fluid particles
 * (0 when there are none). Collective. */
PetscErrorCode liquid_state_bounds(sim *s, double *rho_dev, double *mach);

/* Where the density bound breaks, to tell a few squeezed particles from the bulk: how many
 * fluid particles lie beyond `limit` in |rho/rho0 - 1|, and the position of the one
 * farthest from rho0 (the lowest gid among equals, so any rank count names the same one;
 * (0, 0) when there is no fluid). Collective. */
PetscErrorCode liquid_state_worst(sim *s, double limit, PetscInt64 *n_over, double worst_x[2]);

#endif
