/* Liquid below a membrane layer (membrane_leak.h). The layer's positions are
 * gathered by a sum over ranks (each particle is owned once, the other
 * entries are zero), so every rank tests its fluid against the same line and
 * the count does not depend on the decomposition. */
#include <math.h>
#include "dmhs/membrane_leak.h"

/* Height of the polyline (xs[k], ys[k]), xs ascending, at x; NAN outside. */
static double polyline_height(const double *xs, const double *ys, PetscInt n, double x) {
  if (n < 2 || x < xs[0] || x > xs[n - 1])
    return NAN;
  PetscInt lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    const PetscInt mid = (lo + hi) / 2;
    if (xs[mid] <= x)
      lo = mid;
    else
      hi = mid;
  }
  const double w = xs[hi] > xs[lo] ? (x - xs[lo]) / (xs[hi] - xs[lo]) : 0.0;
  return ys[lo] + w * (ys[hi] - ys[lo]);
}

PetscErrorCode membrane_leak_count(sim *s, const membrane_layout *m, PetscInt64 *n_inside,
                                   PetscInt64 *n_through) {
  const particles *ps = &s->ps;
  const PetscInt n = m->n_columns, bottom = m->layers - 1;
  double *line; /* x and y of every column's top particle, then of its bottom one */
  PetscInt64 count[2] = {0, 0};
  PetscFunctionBeginUser;
  PetscCheck(m->layers >= 2, s->comm, PETSC_ERR_ARG_OUTOFRANGE,
             "membrane_leak_count: %" PetscInt_FMT " layers", m->layers);
  PetscCall(PetscCalloc1(4 * n, &line));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    const PetscInt64 rel = ps->gid[i] - m->g0;
    if (rel < 0 || rel >= (PetscInt64)n * m->layers)
      continue;
    const PetscInt col = (PetscInt)(rel / m->layers), layer = (PetscInt)(rel % m->layers);
    if (layer != 0 && layer != bottom)
      continue;
    double *at = line + (layer == 0 ? 0 : 2 * n);
    at[col] = ps->x[i][0];
    at[n + col] = ps->x[i][1];
  }
  PetscCallMPI(
      MPI_Allreduce(MPI_IN_PLACE, line, (PetscMPIInt)(4 * n), MPI_DOUBLE, MPI_SUM, s->comm));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->type[i] != PTYPE_FLUID)
      continue;
    const double yt = polyline_height(line, line + n, n, ps->x[i][0]);
    const double yb = polyline_height(line + 2 * n, line + 3 * n, n, ps->x[i][0]);
    if (!isnan(yb) && ps->x[i][1] < yb)
      count[1]++;
    else if (!isnan(yt) && ps->x[i][1] < yt)
      count[0]++;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, count, 2, MPIU_INT64, MPI_SUM, s->comm));
  *n_inside = count[0];
  *n_through = count[1];
  PetscCall(PetscFree(line));
  PetscFunctionReturn(0);
}
