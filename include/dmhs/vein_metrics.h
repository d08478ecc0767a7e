/* Diagnostics of the deep-vein valve (src/diag/vein_metrics.c): an object
 * the vein scene creates with the geometry it built and calls after every
 * step. It owns <output_dir>/vein.csv, vein-sinus.csv and vein-summary.csv,
 * the crossing count and the measurement point (doc/user-guide.md, "Scene
 * vein"; definitions in doc/theory.md, "Vein metrics"). */
#ifndef DMHS_VEIN_METRICS_H
#define DMHS_VEIN_METRICS_H
#include "dmhs/sim.h"

struct checkpoint_io;

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

typedef struct vein_metrics vein_metrics;

PetscErrorCode vein_metrics_create(sim *s, const vein_layout *layout, vein_metrics **out);
/* After every step (and at step 0): crossings every crossing_interval steps;
 * stress fields, CSV rows and the measurement point at output times. */
PetscErrorCode vein_metrics_diagnose(vein_metrics *v, sim *s);
/* End of the run: summary (time-averaged displacement and per-cycle peak
 * stress with standard deviations, peak inlet velocities, crossings). */
PetscErrorCode vein_metrics_finish(vein_metrics *v, sim *s);
PetscErrorCode vein_metrics_checkpoint_write(vein_metrics *v, struct checkpoint_io *io);
PetscErrorCode vein_metrics_checkpoint_read(vein_metrics *v, sim *s, struct checkpoint_io *io);
PetscErrorCode vein_metrics_destroy(vein_metrics **v);

#endif
