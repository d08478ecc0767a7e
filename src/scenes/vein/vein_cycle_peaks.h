/* The measurement point's peak stress per drive cycle (vein_metrics.c's summary), from its
 * history of output rows. */
#ifndef DMHS_VEIN_CYCLE_PEAKS_H
#define DMHS_VEIN_CYCLE_PEAKS_H
#include <petscsys.h>

/* hist[k] = {t, stress, displacement}, k < n, in time order from the row at which the point
 * was chosen. Writes into peaks the largest stress of every whole cycle of period T that ends
 * by t_end and whose first quarter (the probe time) the point was already followed in;
 * returns their count (at most floor(t_end / T) + 1 entries are written). Rows and the run's
 * end land within a step of their nominal times (1.0000013 for 1 s, a run may end at
 * 15.999999 for 16 s): times are matched within 1e-3 T, far above a step and far below an
 * output interval. */
PetscInt vein_cycle_peaks(const double (*hist)[3], PetscInt n, double T, double t_end,
                          double *peaks);
/* the size peaks needs */
PetscInt vein_cycle_peaks_max(double T, double t_end);
#endif
