/* Module peristalsis: the peristaltic wave of the intestine scene
 * as a schedule of up (+1), down (-1) or no (0) force on each pocket's
 * membrane segment per sub-period t_w, plus the support that holds the
 * membrane in its haustral shape (doc/theory.md, "Peristalsis and tracking"). */
#ifndef DMHS_PERISTALSIS_H
#define DMHS_PERISTALSIS_H
#include "dmhs/module.h"

/* Solid particles of pocket k's membrane segment have segment = PERISTALSIS_SEGMENT0 + k
 * (the segment field exists with this module; 0 = none). */
#define PERISTALSIS_SEGMENT0 1

PetscErrorCode peristalsis_module_create(module **m);
/* Scene geometry: n_pockets (N + 1) pockets of length b [m], pocket k spanning
 * [x_left + k b, x_left + (k+1) b]. Call before the module's options pass. */
PetscErrorCode peristalsis_set_geometry(module *m, PetscInt n_pockets, double b, double x_left);
/* Schedule value (-1, 0, +1) of pocket k at time t; the sub-period index r
 * (wave-relative, -1 before the wave starts or after the last wave). */
int peristalsis_value(const module *m, double t, PetscInt k);
PetscInt peristalsis_subperiod(const module *m, double t);
/* The force factor actually applied: the value blended with the previous
 * sub-period's over the ramp (smoothstep). */
double peristalsis_amplitude(const module *m, double t, PetscInt k);
/* Resolved t_w [s], period T_w [s] (rows x t_w), H, rows of the schedule. */
PetscErrorCode peristalsis_get(const module *m, double *t_w, double *T_w, PetscInt *H,
                               PetscInt *rows, double *delay);
/* -peristalsis_waves: the waves before the force stops (0: until the run's end). */
PetscInt peristalsis_waves(const module *m);
/* The generated (published) schedule: pocket k of n_pockets in sub-period r of a
 * period of 2N+5 sub-periods: -1 if r = 2k-1, +1 if r in 2k+1 .. 2k+H (mod 2N+5). */
int peristalsis_spec_value(PetscInt n_pockets, PetscInt H, PetscInt r, PetscInt k);

#endif
