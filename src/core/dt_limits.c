/* Time-step limits (dt_limits.h). */
#include <math.h>
#include "dmhs/dt_limits.h"

/* Limits from pair geometry (an arm, a stretch, a closest approach) may see a
 * ghost's periodic image a rounding apart on different rank counts: rounded
 * down to 2^-24 relative, they agree bit for bit on any decomposition but for
 * a value within an ulp of a grid point. */
static double dt_limit_round(double v) {
  if (!isfinite(v) || v <= 0)
    return v;
  int e;
  const double m = frexp(v, &e);
  return ldexp(floor(m * 16777216.0) / 16777216.0, e);
}

PetscErrorCode dt_limits_add(dt_limits *l, const char *name, const char *formula, double value) {
  PetscFunctionBeginUser;
  value = dt_limit_round(value);
  PetscCheck(l->n < DT_LIMITS_MAX, PETSC_COMM_SELF, PETSC_ERR_PLIB, "too many time-step limits");
  PetscCall(PetscStrncpy(l->item[l->n].name, name, sizeof(l->item[l->n].name)));
  PetscCall(PetscStrncpy(l->item[l->n].formula, formula, sizeof(l->item[l->n].formula)));
  l->item[l->n].value = value;
  l->n++;
  PetscFunctionReturn(0);
}

double dt_limits_min(const dt_limits *l, int *which) {
  double best = INFINITY;
  *which = -1;
  for (int k = 0; k < l->n; k++)
    if (l->item[k].value < best) {
      best = l->item[k].value;
      *which = k;
    }
  return best;
}
