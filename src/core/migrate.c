/* Migration. On one rank: wrap positions into the periodic box and stop the
 * run, naming the particle, when one leaves the box along a closed direction. */
#include "dmhs/sim.h"
#include "dmhs/migrate.h"
#include "dmhs/events.h"

PetscErrorCode migrate_particles(sim *s) {
  particles *ps = &s->ps;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(events.migrate, 0, 0, 0, 0));
  ps->n_ghost = 0;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    domain_wrap(&s->dom, ps->x[i]);
    PetscCheck(domain_contains(&s->dom, ps->x[i]), PETSC_COMM_SELF, PETSC_ERR_FP,
               "particle gid %" PetscInt64_FMT " escaped the domain at step %" PetscInt_FMT
               ", t = %g s: x = (%g, %g) outside [%g, %g] x [%g, %g]; the run is unstable or a wall leaks "
               "(try a smaller -dt)",
               ps->gid[i], s->step, s->t, ps->x[i][0], ps->x[i][1], s->dom.lo[0], s->dom.hi[0], s->dom.lo[1],
               s->dom.hi[1]);
  }
  PetscCall(PetscLogEventEnd(events.migrate, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
