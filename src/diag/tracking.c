/* Tracked fluid sets (see tracking.h): pocket counts, the front x_F and
 * least-squares slopes (GSL). Positions are summed as 64-bit integers of
 * TRACKING_FIXED = 1e-12 m, so that the MPI sum is exact and the CSV does not
 * depend on the rank count or the particles' order. */
#include <math.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>
#include "dmhs/tracking.h"

PetscInt tracking_pocket(double x, PetscInt n_pockets, double b, double x_left) {
  const double u = (x - x_left) / b;
  if (u < 0)
    return 0;
  if (u >= (double)n_pockets)
    return n_pockets;
  return (PetscInt)floor(u);
}

static inline PetscInt64 tracking_fixed(double x) {
  return (PetscInt64)llround(x / TRACKING_FIXED);
}

PetscErrorCode tracking_count(sim *s, PetscInt tracer, PetscInt n_pockets, double b, double x_left,
                              PetscInt64 counts[], PetscInt64 *n, double *mean_x) {
  const particles *ps = &s->ps;
  PetscInt64 *buf;
  PetscFunctionBeginUser;
  /* a particle past the last pocket (over the weir, or parked in the lot at a place
   * set by its gid) is in pocket N+1, counted at its start x_left + (N+1) b */
  const double x_out = x_left + (double)n_pockets * b;
  PetscCall(PetscCalloc1(n_pockets + 3, &buf));
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (ps->tracer[i] != tracer)
      continue;
    buf[tracking_pocket(ps->x[i][0], n_pockets, b, x_left)]++;
    buf[n_pockets + 1]++;
    buf[n_pockets + 2] += tracking_fixed(PetscMin(ps->x[i][0], x_out));
  }
  PetscCallMPI(
      MPI_Allreduce(MPI_IN_PLACE, buf, (PetscMPIInt)(n_pockets + 3), MPIU_INT64, MPI_SUM, s->comm));
  for (PetscInt k = 0; k <= n_pockets; k++)
    counts[k] = buf[k];
  *n = buf[n_pockets + 1];
  *mean_x = *n > 0 ? (double)buf[n_pockets + 2] * TRACKING_FIXED / (double)*n : NAN;
  PetscCall(PetscFree(buf));
  PetscFunctionReturn(0);
}

PetscErrorCode tracking_mean_displacement(sim *s, PetscBool (*sel)(const sim *, PetscInt, void *),
                                          void *ctx, int d, double *mean, PetscInt64 *n) {
  const particles *ps = &s->ps;
  PetscInt64 buf[2] = {0, 0};
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < ps->n_owned; i++) {
    if (!sel(s, i, ctx))
      continue;
    buf[0]++;
    buf[1] += tracking_fixed(ps->x[i][d] - ps->x0[i][d]);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, buf, 2, MPIU_INT64, MPI_SUM, s->comm));
  *n = buf[0];
  *mean = buf[0] > 0 ? (double)buf[1] * TRACKING_FIXED / (double)buf[0] : 0.0;
  PetscFunctionReturn(0);
}

PetscErrorCode tracking_slope(const double *t, const double *y, PetscInt n, double *slope) {
  double c0, c1, cov00, cov01, cov11, sumsq;
  PetscFunctionBeginUser;
  *slope = NAN;
  if (n < 2)
    PetscFunctionReturn(0);
  gsl_set_error_handler_off();
  const int err = gsl_fit_linear(t, 1, y, 1, (size_t)n, &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  PetscCheck(!err, PETSC_COMM_SELF, PETSC_ERR_LIB, "gsl_fit_linear: %s", gsl_strerror(err));
  *slope = c1;
  PetscFunctionReturn(0);
}
