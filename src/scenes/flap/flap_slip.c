/* The no-slip measure on the flap's faces (flap_strip.h). */
#include <math.h>
#include "flap_strip.h"

/* No-slip at the flap's faces. For every free row c below the tip and each
 * face (layer l = 0 upstream, 1 downstream), with the flap's local tangent t
 * (mid-line from row c-1 to c+1) and normal n (layer 0 -> layer 1), take the
 * fluid particles in the strip |(x_i - x_P).t| < dx beside the face particle
 * P, at distance d = sigma (x_i - x_P).n - dx/2 from the face surface
 * (sigma = -1, +1 for l = 0, 1; the surface lies half a spacing outside the
 * particle centres) with -dx/2 < d <= 2.5 dx, and fit the relative velocity
 * v_i - v_P linearly in d (least squares, both components). The fit's value
 * at d = 0 is the liquid's velocity on the face relative to the flap: no-slip
 * makes it vanish, to within the discretisation. Returned, normalised by the
 * largest fluid speed u_max:
 *   slip = mean over faces and rows of |u(d = 0)|,
 *   near = mean |v_i - v_P| of the first fluid layer (d <= dx), for scale:
 *          what a slipping flap would show. */
PetscErrorCode flap_slip(const flap_strip *st, sim *s, double *slip, double *near, double *umax) {
  const particles *ps = &s->ps;
  const double dx = st->lay.dx;
  const PetscInt c0 = st->lay.n_clamp, n_rows = st->lay.n_rows - 1 - c0,
                 n_faces = 2 * PetscMax(n_rows, 0);
  double u2 = 0, sum_slip = 0, n_slip = 0, *acc;
  enum { S, SD, SDD, SU0, SU1, SUD0, SUD1, NEAR, NNEAR, N_ACC };
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(N_ACC * n_faces + 1, &acc));
  for (PetscInt i = 0; i < ps->n_owned; i++)
    if (ps->type[i] == PTYPE_FLUID)
      u2 = PetscMax(u2, ps->v[i][0] * ps->v[i][0] + ps->v[i][1] * ps->v[i][1]);
  /* the flap's particles come from the replicated strip (flap_strip_gather), the
   * liquid from each rank's owned particles; the sums of every face are reduced over ranks */
  for (PetscInt c = c0; c + 1 < st->lay.n_rows; c++) {
    double t[2] = {0, 0};
    for (int l = 0; l < 2; l++) {
      t[0] += 0.5 * (st->x[2 * (c + 1) + l][0] - st->x[2 * (c - 1) + l][0]);
      t[1] += 0.5 * (st->x[2 * (c + 1) + l][1] - st->x[2 * (c - 1) + l][1]);
    }
    const double tl = hypot(t[0], t[1]);
    t[0] /= tl;
    t[1] /= tl;
    const double n[2] = {t[1], -t[0]};
    for (int l = 0; l < 2; l++) {
      const PetscInt P = 2 * c + l;
      const double sigma = l == 0 ? -1.0 : 1.0;
      double *A = acc + N_ACC * (2 * (c - c0) + l);
      for (PetscInt i = 0; i < ps->n_owned; i++) {
        if (ps->type[i] != PTYPE_FLUID)
          continue;
        double r[2] = {ps->x[i][0] - st->x[P][0], ps->x[i][1] - st->x[P][1]};
        domain_min_image(&s->dom, r);
        const double d = sigma * (r[0] * n[0] + r[1] * n[1]) - 0.5 * dx,
                     along = r[0] * t[0] + r[1] * t[1];
        if (fabs(along) >= dx || d <= -0.5 * dx || d > 2.5 * dx)
          continue;
        const double u[2] = {ps->v[i][0] - st->v[P][0], ps->v[i][1] - st->v[P][1]};
        A[S] += 1;
        A[SD] += d;
        A[SDD] += d * d;
        A[SU0] += u[0];
        A[SU1] += u[1];
        A[SUD0] += u[0] * d;
        A[SUD1] += u[1] * d;
        if (d <= dx) {
          A[NEAR] += hypot(u[0], u[1]);
          A[NNEAR] += 1;
        }
      }
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, acc, (PetscMPIInt)(N_ACC * n_faces), MPI_DOUBLE, MPI_SUM,
                             s->comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &u2, 1, MPI_DOUBLE, MPI_MAX, s->comm));
  *umax = sqrt(u2);
  double sum_near = 0, n_near = 0;
  for (PetscInt k = 0; k < n_faces; k++) {
    const double *A = acc + N_ACC * k;
    sum_near += A[NEAR];
    n_near += A[NNEAR];
    const double det =
        A[S] * A[SDD] - A[SD] * A[SD]; /* S^2 var(d): needs points spread across the layers */
    if (A[S] < 3 || det < A[S] * A[S] * 0.09 * dx * dx)
      continue;
    const double u0[2] = {(A[SDD] * A[SU0] - A[SD] * A[SUD0]) / det,
                          (A[SDD] * A[SU1] - A[SD] * A[SUD1]) / det};
    sum_slip += hypot(u0[0], u0[1]);
    n_slip += 1;
  }
  PetscCall(PetscFree(acc));
  *slip = n_slip > 0 && *umax > 0 ? sum_slip / n_slip / *umax : NAN;
  *near = n_near > 0 && *umax > 0 ? sum_near / n_near / *umax : NAN;
  PetscFunctionReturn(0);
}
