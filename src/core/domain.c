/* The simulation box: minimum image and wrapping along periodic directions. */
#include <math.h>
#include "dmhs/domain.h"

void domain_min_image(const domain *d, double dx[DMHS_DIM]) {
  for (int k = 0; k < DMHS_DIM; k++) {
    if (!d->periodic[k])
      continue;
    const double L = domain_length(d, k);
    /* most separations are shorter than half a period, and round(dx / L) is then 0: the
     * division only where it can be other (the margin keeps dx / L's rounding out of it) */
    if (fabs(dx[k]) > 0.4999 * L)
      dx[k] -= L * round(dx[k] / L);
    else
      dx[k] += 0.0; /* what the formula leaves: -0 becomes +0, any other value stays */
  }
}

void domain_wrap(const domain *d, double x[DMHS_DIM]) {
  for (int k = 0; k < DMHS_DIM; k++) {
    if (!d->periodic[k])
      continue;
    double L = domain_length(d, k);
    /* floor handles particles more than one period away (never expected, but exact) */
    x[k] -= L * floor((x[k] - d->lo[k]) / L);
    /* round-off: (x - lo)/L may round up to a whole number just below hi, leaving x
     * a few ulps below lo; and x + L may round to hi */
    if (x[k] < d->lo[k])
      x[k] += L;
    if (x[k] >= d->hi[k])
      x[k] = d->lo[k];
  }
}

PetscBool domain_contains(const domain *d, const double x[DMHS_DIM]) {
  for (int k = 0; k < DMHS_DIM; k++)
    if (!d->periodic[k] && (x[k] < d->lo[k] || x[k] > d->hi[k]))
      return PETSC_FALSE;
  return PETSC_TRUE;
}

PetscErrorCode domain_check_ghost_width(const domain *d, double width) {
  PetscFunctionBeginUser;
  for (int k = 0; k < DMHS_DIM; k++) {
    PetscCheck(d->hi[k] > d->lo[k], PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
               "domain: empty box along axis %d: [%g, %g]", k, d->lo[k], d->hi[k]);
    PetscCheck(!d->periodic[k] || domain_length(d, k) > 2.0 * width, PETSC_COMM_SELF,
               PETSC_ERR_ARG_OUTOFRANGE,
               "domain: periodic length %g m along axis %d is not larger than twice the "
               "interaction reach %g m; make the box longer or the support (-sph_h) smaller",
               domain_length(d, k), k, width);
  }
  PetscFunctionReturn(0);
}
