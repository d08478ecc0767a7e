/* Progress line and end-of-run summary (rank 0 prints). */
#include <math.h>
#include "dmhs/sim.h"
#include "dmhs/progress.h"

static double particle_steps_per_second(const sim *s, double seconds) {
  return seconds > 0 ? (double)s->particle_steps / seconds : 0.0;
}

PetscErrorCode progress_print(sim *s) {
  const particles *ps = &s->ps;
  const sph_params *sp = sph_params_get(s); /* NULL: no liquid (solids only) */
  double local[2] = {0, 0}, global[2];
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    local[0] = PetscMax(local[0], ps->v[i][0] * ps->v[i][0] + ps->v[i][1] * ps->v[i][1]);
    if (ps->type[i] == PTYPE_FLUID && sp)
      local[1] = PetscMax(local[1], PetscAbsReal(ps->rho[i] / sp->rho0 - 1.0));
  }
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, s->comm));
  PetscCall(partition_measure_imbalance(&s->part, s)); /* mpi: max/mean owned over ranks */
  const double elapsed = MPI_Wtime() - s->loop_start_wtime;
  const double rate = particle_steps_per_second(s, elapsed);
  /* since this session's start (a restart begins at t > 0) */
  const double done = s->t - s->io.restart_t;
  /* the last step may pass t_end by up to dt/2: nothing is left then (not "-0.0 s") */
  const double left = s->t_end - s->t > 0 ? s->t_end - s->t : 0.0;
  const double eta = done > 0 ? elapsed * left / done : 0.0;
  PetscCall(PetscPrintf(s->comm,
                        "step %8" PetscInt_FMT
                        "  t %.6e s  dt %.3e s (%s)  particle-steps/s %.3e  ETA %7.1f s  "
                        "max|v| %.3e m/s  max|rho/rho0-1| %.2e  imbalance %.3f\n",
                        s->step, s->t, s->dt, s->ts.binding[0] ? s->ts.binding : "no limit", rate,
                        eta, sqrt(global[0]), global[1], s->part.imbalance));
  PetscFunctionReturn(0);
}

PetscErrorCode progress_summary(sim *s) {
  PetscInt n_owned = s->ps.n_owned, n_total;
  char t_text[32];
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&n_owned, &n_total, 1, MPIU_INT, MPI_SUM, s->comm));
  snprintf(t_text, sizeof(t_text), "%g", s->t); /* C formatting: PETSc's %g prints "1." */
  PetscCall(
      PetscPrintf(s->comm,
                  "dmhs summary: scene %s, %" PetscInt_FMT " particles, %d rank(s), %" PetscInt_FMT
                  " steps to t = %s s, %" PetscInt_FMT " neighbour-list builds, step loop %.3f s, "
                  "particle-steps/s: %.4e\n",
                  s->scn->name, n_total, (int)s->size, s->step, t_text, s->n_rebuilds,
                  s->loop_seconds, particle_steps_per_second(s, s->loop_seconds)));
  PetscFunctionReturn(0);
}
