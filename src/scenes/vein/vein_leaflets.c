/* The vein's leaflets replicated on every rank (vein_leaflets.h). */
#include "vein_leaflets.h"

PetscErrorCode vein_leaflets_create(const vein_layout *lay, vein_leaflets *lf) {
  PetscFunctionBeginUser;
  lf->lay = *lay;
  for (int k = 0; k < 2; k++)
    lf->n_leaf[k] = 2 * lay->leaflet[k].n_columns;
  PetscCall(PetscMalloc1(lf->n_leaf[0] + lf->n_leaf[1], &lf->x));
  PetscFunctionReturn(0);
}

PetscErrorCode vein_leaflets_destroy(vein_leaflets *lf) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(lf->x));
  PetscFunctionReturn(0);
}

PetscInt vein_leaflets_index(const vein_leaflets *lf, PetscInt64 gid, int *which) {
  for (int w = 0; w < 2; w++) {
    const PetscInt64 k = gid - lf->lay.leaflet[w].first_gid;
    if (k >= 0 && k < lf->n_leaf[w]) {
      *which = w;
      return (PetscInt)k + (w ? lf->n_leaf[0] : 0);
    }
  }
  return -1;
}

PetscErrorCode vein_leaflets_gather(vein_leaflets *lf, sim *s) {
  const PetscInt n = lf->n_leaf[0] + lf->n_leaf[1];
  PetscFunctionBeginUser;
  PetscCall(PetscArrayzero(lf->x, n));
  for (PetscInt i = 0; i < s->ps.n_owned; i++) {
    int w;
    const PetscInt k = vein_leaflets_index(lf, s->ps.gid[i], &w);
    if (k < 0)
      continue;
    lf->x[k][0] = s->ps.x[i][0];
    lf->x[k][1] = s->ps.x[i][1];
  }
  PetscCallMPI(
      MPI_Allreduce(MPI_IN_PLACE, lf->x, (PetscMPIInt)(2 * n), MPI_DOUBLE, MPI_SUM, s->comm));
  PetscFunctionReturn(0);
}

void vein_leaflets_column_mid(const vein_leaflets *lf, int w, PetscInt c, double m[2]) {
  const double(*x)[2] = lf->x + (w ? lf->n_leaf[0] : 0);
  m[0] = 0.5 * (x[2 * c][0] + x[2 * c + 1][0]);
  m[1] = 0.5 * (x[2 * c][1] + x[2 * c + 1][1]);
}
