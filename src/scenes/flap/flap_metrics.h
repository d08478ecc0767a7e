/* Diagnostics of the flap scene (src/scenes/flap/flap_*.c), with the geometry the
 * scene built:
 *   "flap_crossings" (flap_crossings.c): every -flap_crossing_interval steps
 *     and at output times, each fluid particle beside the flap (within 3 dx of
 *     its mid-line, between its lowest and highest rows) records its side; one
 *     seen on the other side since the last check counts as a crossing (must
 *     stay 0). Its state (count and side of every fluid gid) travels in the
 *     checkpoint.
 *   "flap" (flap_rows.c): <output_dir>/flap.csv at every output time:
 *     t, tip_dx, tip_dy [m] (mean displacement of the top row), crossings,
 *     slip (the liquid's velocity extrapolated onto the flap's faces, relative
 *     to the flap, over the largest fluid speed: flap_slip.c), near (the first
 *     fluid layer's speed relative to the flap, same scale), u_max [m/s];
 *     a restart continues it (csv.h); at the end a report line and
 *     <output_dir>/flap-particles.csv (x, y, vx, vy, type, rows in gid order
 *     whatever the rank count) for plots. */
#ifndef DMHS_FLAP_METRICS_H
#define DMHS_FLAP_METRICS_H
#include "dmhs/sim.h"

typedef struct flap_layout {
  PetscInt64 first_gid; /* row c, layer l (0 upstream): first_gid + 2c + l */
  PetscInt n_rows;      /* rows of the strip, the clamped ones included */
  PetscInt n_clamp;     /* clamped rows at the bottom */
  PetscInt height_rows; /* rows above the wall (the flap's height in dx) */
  double dx;            /* spacing [m] */
  PetscInt n_fluid;     /* fluid gids are 0 .. n_fluid - 1 */
} flap_layout;

/* Registers "flap_crossings", checking every `interval` steps (>= 1) and at output times. */
PetscErrorCode flap_crossings_register(sim *s, const flap_layout *lay, PetscInt interval,
                                       diagnostic **out);
/* The crossings counted so far (the same on every rank). */
PetscInt flap_crossings_count(const diagnostic *crossings);
/* Registers "flap"; its rows report the count of `crossings`. */
PetscErrorCode flap_rows_register(sim *s, const flap_layout *lay, const diagnostic *crossings);

#endif
