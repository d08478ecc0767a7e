/* Weakly compressible bounds of the liquid (liquid_state.h). */
#include <math.h>
#include "dmhs/liquid_state.h"

PetscErrorCode liquid_state_bounds(sim *s, double *rho_dev, double *mach) {
  const particles *ps = &s->ps;
  const sph_params *sp = sph_params_get(s);
  double buf[2] = {0, 0};
  PetscFunctionBeginUser;
  PetscCheck(sp, s->comm, PETSC_ERR_ARG_WRONGSTATE,
             "the liquid's compressibility bounds need the sph module (scene %s has none)",
             s->scn->name);
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID)
      continue;
    buf[0] = PetscMax(buf[0], fabs(ps->rho[i] / sp->rho0 - 1.0));
    buf[1] = PetscMax(buf[1], hypot(ps->v[i][0], ps->v[i][1]) / sp->c0);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, buf, 2, MPI_DOUBLE, MPI_MAX, s->comm));
  *rho_dev = buf[0];
  *mach = buf[1];
  PetscFunctionReturn(0);
}
