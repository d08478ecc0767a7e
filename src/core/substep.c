/* Solid sub-cycling (see substep.h). Bitwise rank invariant like the step it
 * refines: the sub-steps touch owned solid rows only, and the ghosts' positions
 * are refreshed before every evaluation of the bonds and angles. */
#include "dmhs/sim.h"
#include "dmhs/substep.h"
#include "dmhs/halo.h"
#include "dmhs/events.h"

/* module filters: the solids' own forces (bonds, angles), and every other */
static PetscBool substep_internal(const module *m) {
  return m->solid_internal;
}

static PetscBool substep_external(const module *m) {
  return m->solid_internal ? PETSC_FALSE : PETSC_TRUE;
}

/* A sub-step's evaluation: the solids' own modules, which write no drho (the
 * step's next force evaluation zeroes it). */
static PetscErrorCode substep_internal_forces(sim *s) {
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  PetscCall(PetscArrayzero(ps->a, ps->n_owned + ps->n_ghost));
  PetscCall(sim_add_module_forces(s, substep_internal));
  PetscFunctionReturn(0);
}

PetscErrorCode substep_solids(sim *s) {
  particles *ps = &s->ps;
  static const char *const positions[] = {"x"};
  const PetscInt n = s->ts.n_sub;
  const double h = s->dt / (double)n, half = 0.5 * h;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.substeps, 0, 0, 0, 0));
  /* first half kick with the whole acceleration of the last evaluation */
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_SOLID)
      continue;
    for (int k = 0; k < DMHS_DIM; k++)
      ps->v[i][k] += half * ps->a[i][k];
  }
  for (PetscInt sub = 0; sub < n; sub++) {
    for (PetscInt i = 0; i < ps->n_owned; i++) {
      if (ps->type[i] != PTYPE_SOLID)
        continue;
      for (int k = 0; k < DMHS_DIM; k++)
        ps->x[i][k] += h * ps->v[i][k];
    }
    if (sub == n - 1)
      break; /* the step's force evaluation gives the last one */
    PetscCall(halo_forward(&s->hal, ps, positions, 1));
    PetscCall(substep_internal_forces(s));
    /* the second half kick of this sub-step and the first of the next */
    for (PetscInt i = 0; i < ps->n_owned; i++) {
      if (ps->type[i] != PTYPE_SOLID)
        continue;
      for (int k = 0; k < DMHS_DIM; k++)
        ps->v[i][k] += h * (ps->a_hold[i][k] + ps->a[i][k]);
    }
  }
  /* the liquid sees the solid's velocity predicted for the end of the step, as
   * its own (integrate_first_half): the last sub-step's half-kicked velocity
   * plus the other half with the acceleration it started from. With one
   * sub-step that is v^n + dt a^n, the plain step's. */
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_SOLID)
      continue;
    for (int k = 0; k < DMHS_DIM; k++)
      ps->v_est[i][k] = ps->v[i][k] + half * (n > 1 ? ps->a_hold[i][k] + ps->a[i][k] : ps->a[i][k]);
  }
  PetscCall(PetscLogEventEnd(events.substeps, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode substep_compute_forces(sim *s) {
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  PetscCall(sim_compute_module_forces(s, substep_internal));
  for (PetscInt i = 0; i < ps->n_owned; i++)
    for (int k = 0; k < DMHS_DIM; k++)
      ps->a_hold[i][k] = ps->a[i][k];
  PetscCall(sim_add_module_forces(s, substep_external));
  for (PetscInt i = 0; i < ps->n_owned; i++)
    for (int k = 0; k < DMHS_DIM; k++)
      ps->a_hold[i][k] = ps->a[i][k] - ps->a_hold[i][k];
  PetscFunctionReturn(0);
}
