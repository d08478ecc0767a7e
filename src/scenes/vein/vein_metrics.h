/* Diagnostics of the deep-vein valve, registered by the vein scene with the
 * geometry it built: "vein_crossings" (src/scenes/vein/vein_crossings.c), the check
 * that no liquid crosses a leaflet, every crossing_interval steps and at output
 * times; "vein" (src/scenes/vein/vein_metrics.c), at output times, owning
 * <output_dir>/vein.csv, vein-sinus.csv and vein-summary.csv and the
 * measurement point (doc/guide/scene-vein.md, "Outputs and plots"; definitions in
 * doc/theory.md, "Vein metrics"). */
#ifndef DMHS_VEIN_METRICS_H
#define DMHS_VEIN_METRICS_H
#include "dmhs/sim.h"

/* Fluid that starts in the sinus (between a leaflet and the sinus wall). */
#define VEIN_TRACER_SINUS 1

typedef struct vein_leaflet {
  PetscInt64 first_gid; /* column c, layer l: first_gid + 2c + l; column 0 is the clamp */
  PetscInt n_columns;   /* clamp included */
  int sinus_layer;      /* the layer that faces the sinus (0) */
} vein_leaflet;

typedef struct vein_layout {
  double dx, width, period_T; /* spacing [m], channel width [m], drive period [s] */
  double x_station;           /* inlet station, away from the sinus [m] */
  double x_sinus0, sinus_length;
  double rest_gap;            /* tip-to-tip distance at rest [m] */
  vein_leaflet leaflet[2];    /* 0 upper, 1 lower */
  PetscInt crossing_interval; /* steps between crossing checks */
  double probe_time;          /* when the measurement point is chosen [s] */
  /* reported beside the results */
  double leaflet_length, g0, ka_ref;
} vein_layout;

/* Registers "vein_crossings" (lay->crossing_interval >= 1). */
PetscErrorCode vein_crossings_register(sim *s, const vein_layout *lay, diagnostic **out);
/* The crossings counted so far, over all ranks. Collective. */
PetscErrorCode vein_crossings_total(const diagnostic *crossings, sim *s, PetscInt64 *total);
/* Registers "vein"; its rows report the count of `crossings`. At the end: the
 * summary (time-averaged displacement and per-cycle peak stress with standard
 * deviations, peak inlet velocities, crossings). */
PetscErrorCode vein_metrics_register(sim *s, const vein_layout *lay, const diagnostic *crossings);

#endif
