/* Per-particle stress diagnostics (src/diag/stress.c), for scenes that ask
 * for them (the vein): shear rate, virial stress and its magnitude, pressure
 * force, speed and displacement, as optional snapshot fields. */
#ifndef DMHS_STRESS_H
#define DMHS_STRESS_H
#include "dmhs/sim.h"

/* Enables the fields (scene options pass, before particles are added). */
PetscErrorCode stress_enable(void);
/* Fills the fields of the owned particles from the current state:
 *   stress_i = W_i / V_i, V_i = m_i / rho_i, W_i the sum of every enabled
 *   module's virial (module.h); stress_mag = sqrt(xx^2 + 2 xy^2 + yy^2);
 *   speed = |v|; displacement = |x - x0| (minimum image in periodic x).
 * Collective only in the sense that every rank calls it (no communication). */
PetscErrorCode stress_compute(sim *s);

#endif
