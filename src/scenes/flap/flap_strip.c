/* The flap's particles replicated on every rank (flap_strip.h). */
#include <math.h>
#include "flap_strip.h"

PetscErrorCode flap_strip_create(const flap_layout *lay, flap_strip *st) {
  const PetscInt n = 2 * lay->n_rows;
  PetscFunctionBeginUser;
  st->lay = *lay;
  PetscCall(PetscMalloc3(n, &st->x, n, &st->v, n, &st->x0));
  PetscFunctionReturn(0);
}

PetscErrorCode flap_strip_destroy(flap_strip *st) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree3(st->x, st->v, st->x0));
  PetscFunctionReturn(0);
}

/* mpi: each owner fills its rows, the others add zeros (exact), one Allreduce. */
PetscErrorCode flap_strip_gather(flap_strip *st, sim *s) {
  const particles *ps = &s->ps;
  const PetscInt n = 2 * st->lay.n_rows;
  double *buf;
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(6 * n, &buf));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    const PetscInt64 k = ps->gid[i] - st->lay.first_gid;
    if (k < 0 || k >= n)
      continue;
    for (int d = 0; d < 2; d++) {
      buf[6 * k + d] = ps->x[i][d];
      buf[6 * k + 2 + d] = ps->v[i][d];
      buf[6 * k + 4 + d] = ps->x0[i][d];
    }
  }
  PetscCallMPI(
      MPI_Allreduce(MPI_IN_PLACE, buf, (PetscMPIInt)(6 * n), MPI_DOUBLE, MPI_SUM, s->comm));
  for (PetscInt k = 0; k < n; k++)
    for (int d = 0; d < 2; d++) {
      st->x[k][d] = buf[6 * k + d];
      st->v[k][d] = buf[6 * k + 2 + d];
      st->x0[k][d] = buf[6 * k + 4 + d];
    }
  PetscCall(PetscFree(buf));
  PetscFunctionReturn(0);
}

double flap_strip_midline_x(const flap_strip *st, double y) {
  const double(*x)[2] = (const double(*)[2])st->x;
  for (PetscInt c = 0; c + 1 < st->lay.n_rows; c++) {
    const PetscInt a0 = 2 * c, a1 = 2 * c + 1, b0 = 2 * c + 2, b1 = 2 * c + 3;
    const double ya = 0.5 * (x[a0][1] + x[a1][1]), yb = 0.5 * (x[b0][1] + x[b1][1]);
    if (y < ya || y >= yb)
      continue;
    const double xa = 0.5 * (x[a0][0] + x[a1][0]), xb = 0.5 * (x[b0][0] + x[b1][0]);
    return xa + (xb - xa) * (y - ya) / (yb - ya);
  }
  return NAN;
}

void flap_strip_tip(const flap_strip *st, double d[2]) {
  d[0] = d[1] = 0;
  for (int l = 0; l < 2; l++) {
    const PetscInt r = 2 * (st->lay.n_rows - 1) + l;
    d[0] += 0.5 * (st->x[r][0] - st->x0[r][0]);
    d[1] += 0.5 * (st->x[r][1] - st->x0[r][1]);
  }
}
