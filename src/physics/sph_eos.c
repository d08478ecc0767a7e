/* Pressure from density, once per particle (formulas in sph_eos.h), plus the
 * background pressure -sph_p_background. Ghost rows
 * are evaluated too: the EOS is cheaper than a halo exchange of p. */
#include "dmhs/events.h"
#include "sph_eos.h"
#include "sph_force.h"

/* Every non-wall row of [0, n) for one EOS kind, a constant where it is called so that the
 * kind's switch folds away and the loop vectorises; a select instead of a branch: a wall
 * keeps the pressure the wall pass gives it */
static inline void sph_eos_rows(sph_eos_kind kind, const sph_params *sp, PetscInt n,
                                const PetscInt *restrict type, const double *restrict rho,
                                double *restrict p) {
  const double rho0 = sp->rho0, c0 = sp->c0, p_b = sp->p_background;
  for (PetscInt i = 0; i < n; i++) {
    const double p_eos = sph_eos_pressure(kind, rho[i], rho0, c0) + p_b;
    p[i] = type[i] != PTYPE_WALL ? p_eos : p[i];
  }
}

PetscErrorCode sph_eos_compute(sim *s, const sph_params *sp) {
  particles *ps = &s->ps;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.sph_eos, 0, 0, 0, 0));
  switch (sp->eos) {
  case SPH_EOS_TAIT:
    sph_eos_rows(SPH_EOS_TAIT, sp, n, ps->type, ps->rho, ps->p);
    break;
  case SPH_EOS_LINEAR:
    sph_eos_rows(SPH_EOS_LINEAR, sp, n, ps->type, ps->rho, ps->p);
    break;
  case SPH_EOS_LINEAR_SHIFTED:
    sph_eos_rows(SPH_EOS_LINEAR_SHIFTED, sp, n, ps->type, ps->rho, ps->p);
    break;
  }
  PetscCall(PetscLogFlops(8.0 * (double)n));
  PetscCall(PetscLogEventEnd(events.sph_eos, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
