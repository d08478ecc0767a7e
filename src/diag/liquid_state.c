/* Weakly compressible bounds of the liquid (liquid_state.h). */
#include <math.h>
#include <stdint.h>
#include "dmhs/liquid_state.h"
#include "dmhs/sph.h"

PetscErrorCode liquid_state_bounds(sim *s, double *rho_dev, double *mach) {
  const particles *ps = &s->ps;
  const sph_params *sp = sph_params_get(s);
  double buf[2] = {0, 0};
  PetscFunctionBeginUser;
  PetscCheck(sp, s->comm, PETSC_ERR_ARG_WRONGSTATE,
             "the liquid's compressibility bounds need the sph module (scene %s has none)",
             s->scene_name);
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

PetscErrorCode liquid_state_worst(sim *s, double limit, PetscInt64 *n_over, double worst_x[2]) {
  const particles *ps = &s->ps;
  const sph_params *sp = sph_params_get(s);
  double dev_max = 0;
  PetscInt64 over = 0;
  PetscFunctionBeginUser;
  PetscCheck(sp, s->comm, PETSC_ERR_ARG_WRONGSTATE,
             "the liquid's compressibility bounds need the sph module (scene %s has none)",
             s->scene_name);
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (ps->type[i] == PTYPE_FLUID) {
      const double dev = fabs(ps->rho[i] / sp->rho0 - 1.0);
      dev_max = PetscMax(dev_max, dev);
      over += dev > limit;
    }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &over, 1, MPIU_INT64, MPI_SUM, s->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &dev_max, 1, MPI_DOUBLE, MPI_MAX, s->comm));
  /* the lowest gid at the maximum, then its owner's position (the others add zeros) */
  PetscInt64 gid = INT64_MAX;
  PetscInt row = -1;
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (ps->type[i] == PTYPE_FLUID && fabs(ps->rho[i] / sp->rho0 - 1.0) == dev_max &&
        ps->gid[i] < gid) {
      gid = ps->gid[i];
      row = i;
    }
  PetscInt64 gid_min = gid;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &gid_min, 1, MPIU_INT64, MPI_MIN, s->comm));
  double at[2] = {0, 0};
  if (row >= 0 && gid == gid_min) {
    at[0] = ps->x[row][0];
    at[1] = ps->x[row][1];
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, at, 2, MPI_DOUBLE, MPI_SUM, s->comm));
  *n_over = over;
  worst_x[0] = at[0];
  worst_x[1] = at[1];
  PetscFunctionReturn(0);
}
