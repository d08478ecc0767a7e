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

#endif
