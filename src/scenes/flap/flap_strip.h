/* The flap's particles replicated on every rank (src/scenes/flap/flap_strip.c), for
 * the flap's diagnostics, refreshed per use; and the no-slip measure on its faces. */
#ifndef DMHS_FLAP_STRIP_H
#define DMHS_FLAP_STRIP_H
#include "flap_metrics.h"

typedef struct flap_strip {
  flap_layout lay;
  double (*x)[2], (*v)[2], (*x0)[2]; /* 2 n_rows particles: row c, layer l at 2c + l */
} flap_strip;

PetscErrorCode flap_strip_create(const flap_layout *lay, flap_strip *st);
PetscErrorCode flap_strip_destroy(flap_strip *st);
/* x, v, x0 of every strip particle on every rank. Collective. */
PetscErrorCode flap_strip_gather(flap_strip *st, sim *s);
/* x of the flap's mid-line at height y (linear between rows), or NAN outside it. */
double flap_strip_midline_x(const flap_strip *st, double y);
/* Mean displacement of the top row [m]. */
void flap_strip_tip(const flap_strip *st, double d[2]);
/* The liquid's slip on the faces and the first layer's relative speed, both over
 * u_max, and u_max [m/s] (flap_slip.c). Collective. */
PetscErrorCode flap_slip(const flap_strip *st, sim *s, double *slip, double *near, double *umax);

#endif
