/* Liquid below a membrane layer (membrane_leak.h). The layer's positions are
 * gathered by a sum over ranks (each particle is owned once, the other
 * entries are zero), so every rank tests its fluid against the same line and
 * the count does not depend on the decomposition. */
#include <math.h>
#include "dmhs/membrane_leak.h"

/* Height of the polyline (xs[k], ys[k]), xs ascending, at x; NAN outside. */
static double polyline_height(const double *xs, const double *ys, PetscInt n, double x) {
  if (n < 2 || x < xs[0] || x > xs[n - 1]) return NAN;
  PetscInt lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    const PetscInt mid = (lo + hi) / 2;
    if (xs[mid] <= x) lo = mid;
    else hi = mid;
  }
  const double w = xs[hi] > xs[lo] ? (x - xs[lo]) / (xs[hi] - xs[lo]) : 0.0;
  return ys[lo] + w * (ys[hi] - ys[lo]);
}

PetscErrorCode membrane_leak_count(sim *s, const membrane_layout *m, PetscInt64 *n_below) {
  const particles *ps = &s->ps;
  const PetscInt n = m->n_columns;
  double *line; /* x of every column, then y */
  PetscInt64 below = 0;
  PetscFunctionBeginUser;
  PetscCheck(m->layer >= 0 && m->layer < m->layers, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "membrane_leak_count: layer %" PetscInt_FMT " of %" PetscInt_FMT, m->layer, m->layers);
  PetscCall(PetscCalloc1(2 * n, &line));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    const PetscInt64 rel = ps->gid[i] - m->g0;
    if (rel < 0 || rel >= (PetscInt64)n * m->layers || rel % m->layers != m->layer) continue;
    const PetscInt col = (PetscInt)(rel / m->layers);
    line[col] = ps->x[i][0];
    line[n + col] = ps->x[i][1];
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, line, (PetscMPIInt)(2 * n), MPI_DOUBLE, MPI_SUM, s->comm));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID) continue;
    const double y = polyline_height(line, line + n, n, ps->x[i][0]);
    if (!isnan(y) && ps->x[i][1] < y) below++;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &below, 1, MPIU_INT64, MPI_SUM, s->comm));
  *n_below = below;
  PetscCall(PetscFree(line));
  PetscFunctionReturn(0);
}
