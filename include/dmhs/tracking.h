/* Tracked fluid sets of the intestine scene: counts per pocket,
 * the front position x_F (mean x of the set) and least-squares slopes.
 * Sums over ranks are exact (positions in fixed point, integers reduced), so
 * the results do not depend on the rank count. */
#ifndef DMHS_TRACKING_H
#define DMHS_TRACKING_H
#include "dmhs/sim.h"

/* Fixed-point unit of the position sums [m]. */
#define TRACKING_FIXED 1e-12

/* Pocket of position x: floor((x - x_left)/b) clipped to [0, n_pockets];
 * n_pockets (= N + 1) is the overflow. */
PetscInt tracking_pocket(double x, PetscInt n_pockets, double b, double x_left);
/* Over all ranks, for fluid or parked particles whose tracer field is `tracer` (type ignored):
 * counts[0 .. n_pockets] per pocket (the last is the overflow), the total n
 * and the mean x, where a particle of the overflow counts at x_left + n_pockets b
 * (the parking lot's places are not positions along the colon). Collective. */
PetscErrorCode tracking_count(sim *s, PetscInt tracer, PetscInt n_pockets, double b, double x_left,
                              PetscInt64 counts[], PetscInt64 *n, double *mean_x);
/* Mean over all ranks of (x - x0)[d] of owned particles for which sel(i) is
 * true, exact in fixed point; *n = 0 and *mean = 0 when none. Collective. */
PetscErrorCode tracking_mean_displacement(sim *s, PetscBool (*sel)(const sim *, PetscInt, void *),
                                          void *ctx, int d, double *mean, PetscInt64 *n);
/* Least-squares slope of y(t) (GSL gsl_fit_linear); NAN when fewer than 2 points. */
PetscErrorCode tracking_slope(const double *t, const double *y, PetscInt n, double *slope);

#endif
