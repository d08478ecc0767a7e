/* Solid sub-cycling (see substep.h). Bitwise rank invariant like the step it
 * refines: the sub-steps touch owned rows that move on them only (marked at the
 * step's start from the state alone), and the ghosts' positions (and velocities,
 * when a dashpot reads them) are refreshed before every evaluation of the
 * sub-cycled forces. */
#include <string.h>
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

PetscErrorCode substep_mark_members(sim *s) {
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++)
    ps->substepped[i] = ps->type[i] == PTYPE_SOLID;
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->solid_internal && s->modules[m]->substep_members)
      PetscCall(s->modules[m]->substep_members(s->modules[m], s, ps->substepped));
  PetscFunctionReturn(0);
}

PetscErrorCode substep_solids(sim *s) {
  particles *ps = &s->ps;
  const PetscInt *moves = ps->substepped;
  static const char *const moved[] = {"x", "v"};
  /* positions, and the velocities when a sub-cycled module reads them (dashpots) */
  int n_moved = 1;
  for (int m = 0; m < s->n_modules; m++)
    if (substep_internal(s->modules[m]))
      for (const char *const *r = s->modules[m]->ghost_reads; r && *r; r++)
        if (!strcmp(*r, "v"))
          n_moved = 2;
  const PetscInt n = s->substeps.n;
  const double h = s->dt / (double)n, half = 0.5 * h, half_dt = 0.5 * s->dt;
  /* with one sub-step both schemes are the plain step, written as it is */
  const int respa = s->substeps.respa && n > 1;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.substeps, 0, 0, 0, 0));
  /* first half kick: the sub-cycled share of the last evaluation over h/2 and, with respa,
   * the rest (a_hold) over dt/2; held: the whole acceleration over h/2 */
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (!moves[i])
      continue;
    for (int k = 0; k < DMHS_DIM; k++)
      ps->v[i][k] += respa ? half_dt * ps->a_hold[i][k] + half * (ps->a[i][k] - ps->a_hold[i][k])
                           : half * ps->a[i][k];
  }
  for (PetscInt sub = 0; sub < n; sub++) {
    for (PetscInt i = 0; i < ps->n_owned; i++) {
      if (!moves[i])
        continue;
      for (int k = 0; k < DMHS_DIM; k++)
        ps->x[i][k] += h * ps->v[i][k];
    }
    if (sub == n - 1)
      break; /* the step's force evaluation gives the last one */
    PetscCall(halo_forward(&s->hal, ps, moved, n_moved));
    PetscCall(substep_internal_forces(s));
    /* the second half kick of this sub-step and the first of the next: the sub-cycled
     * forces, and held, the rest too */
    for (PetscInt i = 0; i < ps->n_owned; i++) {
      if (!moves[i])
        continue;
      for (int k = 0; k < DMHS_DIM; k++)
        ps->v[i][k] += respa ? h * ps->a[i][k] : h * (ps->a_hold[i][k] + ps->a[i][k]);
    }
  }
  /* the liquid sees the solid's velocity predicted for the end of the step, as
   * its own (integrate_first_half): the last sub-step's half-kicked velocity
   * plus the kicks still to come with the accelerations at hand (respa: the
   * sub-cycled share over h/2, the rest over dt/2). With one sub-step that is
   * v^n + dt a^n, the plain step's. */
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (!moves[i])
      continue;
    for (int k = 0; k < DMHS_DIM; k++)
      ps->v_est[i][k] =
          ps->v[i][k] + (respa ? half * ps->a[i][k] + half_dt * ps->a_hold[i][k]
                               : half * (n > 1 ? ps->a_hold[i][k] + ps->a[i][k] : ps->a[i][k]));
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
