/* The simulation box: bounds, periodicity, minimum image and wrapping. */
#ifndef DMHS_DOMAIN_H
#define DMHS_DOMAIN_H
#include <petscsys.h>
#include "dmhs/particles.h"

typedef struct domain {
  double lo[DMHS_DIM], hi[DMHS_DIM];
  PetscBool periodic[DMHS_DIM];
} domain;

static inline double domain_length(const domain *d, int k) {
  return d->hi[k] - d->lo[k];
}
/* Replace a separation vector by its nearest periodic image. */
void domain_min_image(const domain *d, double dx[DMHS_DIM]);
/* Map a position into [lo, hi) along periodic directions. */
void domain_wrap(const domain *d, double x[DMHS_DIM]);
/* True when x lies in the box along non-periodic directions (periodic ones always do). */
PetscBool domain_contains(const domain *d, const double x[DMHS_DIM]);
/* The ghost width must cover every interaction reach, and a periodic length must exceed
 * twice of it so that an image never meets its own source. */
PetscErrorCode domain_check_ghost_width(const domain *d, double width);

#endif
