/* Pressure from density, once per particle (formulas in sph_eos.h), plus the
 * background pressure -sph_p_background. Ghost rows
 * are evaluated too: the EOS is cheaper than a halo exchange of p. */
#include "dmhs/events.h"
#include "sph_eos.h"
#include "sph_force.h"

PetscErrorCode sph_eos_compute(sim *s, const sph_params *sp) {
  particles *ps = &s->ps;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.sph_eos, 0, 0, 0, 0));
  for (PetscInt i = 0; i < n; i++)
    if (ps->type[i] != PTYPE_WALL)
      ps->p[i] = sph_eos_pressure_bg(sp, ps->rho[i]);
  PetscCall(PetscLogFlops(8.0 * (double)n));
  PetscCall(PetscLogEventEnd(events.sph_eos, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
