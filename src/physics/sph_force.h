/* Internal interface between the sph module's files (not public). */
#ifndef DMHS_SPH_INTERNAL_H
#define DMHS_SPH_INTERNAL_H
#include "dmhs/sim.h"

/* sph_force.c: momentum (and continuity) sweep over the pair list; the work
 * arrays hold per-particle p/rho^2 and 1/rho (owned and ghost rows) */
typedef struct {
  PetscInt n_alloc;
  double *P, *inv_rho;
} sph_force_work;
PetscErrorCode sph_force_compute(sim *s, sph_force_work *work);
/* sph_stress.c: the SPH virial, pressure force and shear rate (stress diagnostics) */
PetscErrorCode sph_stress_virial(sim *s, double (*W)[3]);
/* sph_density.c: summation density rho_i = sum_j m_j W_ij (self included), owned non-walls */
PetscErrorCode sph_density_summation(sim *s);
/* sph_eos.c: p from rho for every non-wall row (owned and ghost: no communication) */
PetscErrorCode sph_eos_compute(sim *s);
/* sph_wall.c: wall velocity/pressure/density extrapolated from the liquid (Adami 2012) */
typedef struct sph_wall_work sph_wall_work;
PetscErrorCode sph_wall_create(sph_wall_work **w);
PetscErrorCode sph_wall_destroy(sph_wall_work **w);
PetscErrorCode sph_wall_compute(sim *s, sph_wall_work *w);

#endif
