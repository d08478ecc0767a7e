/* struct sim's module helpers: finding an enabled module and the force evaluation over the
 * enabled modules (two phases: every prepare, then every compute). The run itself (options,
 * setup, the step loop, teardown) is the driver's: src/driver/run.c. */
#include <string.h>
#include "dmhs/sim.h"

void sim_default_t_end(sim *s, double t_end) {
  if (!s->t_end_given)
    s->t_end = t_end;
}

module *sim_find_module(const sim *s, const char *name) {
  for (int m = 0; m < s->n_modules; m++)
    if (!strcmp(s->modules[m]->name, name))
      return s->modules[m];
  return NULL;
}

PetscErrorCode sim_add_module_forces(sim *s, module_filter keep) {
  PetscFunctionBeginUser;
  /* phase one: what the computes read from one another, at this evaluation's time */
  for (int m = 0; m < s->n_modules; m++)
    if (s->modules[m]->prepare && (!keep || keep(s->modules[m])))
      PetscCall(s->modules[m]->prepare(s->modules[m], s));
  for (int m = 0; m < s->n_modules; m++)
    if (!keep || keep(s->modules[m]))
      PetscCall(s->modules[m]->compute(s->modules[m], s));
  PetscFunctionReturn(0);
}

PetscErrorCode sim_compute_module_forces(sim *s, module_filter keep) {
  particles *ps = &s->ps;
  const PetscInt n = ps->n_owned + ps->n_ghost;
  const module *first = NULL;
  PetscFunctionBeginUser;
  for (int m = 0; m < s->n_modules && !first; m++)
    if (!keep || keep(s->modules[m]))
      first = s->modules[m];
  /* a pass over the owned rows' rates fewer, when the first module writes them all anyway;
   * the ghost rows' (a few, summed into by pair sweeps and then dropped) still start at 0 */
  if (first && (first->needs & MODULE_SETS_RATES)) {
    s->rates_unset = PETSC_TRUE;
    PetscCall(PetscArrayzero(ps->a + ps->n_owned, ps->n_ghost));
    if (ps->drho)
      PetscCall(PetscArrayzero(ps->drho + ps->n_owned, ps->n_ghost));
  } else {
    PetscCall(PetscArrayzero(ps->a, n));
    if (ps->drho) /* runs without liquid have no density rates */
      PetscCall(PetscArrayzero(ps->drho, n));
  }
  PetscCall(sim_add_module_forces(s, keep));
  PetscCheck(!s->rates_unset, s->comm, PETSC_ERR_PLIB,
             "module %s says it sets the rates (MODULE_SETS_RATES) but did not", first->name);
  PetscFunctionReturn(0);
}
