/* The measurement point's peak stress per drive cycle (vein_cycle_peaks.h). */
#include <math.h>
#include "vein_cycle_peaks.h"

PetscInt vein_cycle_peaks_max(double T, double t_end) {
  return T > 0 ? (PetscInt)floor(t_end / T + 1e-3) + 1 : 0;
}

PetscInt vein_cycle_peaks(const double (*hist)[3], PetscInt n, double T, double t_end,
                          double *peaks) {
  const double tol = 1e-3 * T;
  const PetscInt max_cycles = vein_cycle_peaks_max(T, t_end);
  PetscInt n_cycles = 0;
  if (!n)
    return 0;
  for (PetscInt c = 0; c < max_cycles; c++) {
    double best = -1;
    PetscInt rows = 0;
    for (PetscInt k = 0; k < n; k++)
      if (hist[k][0] > c * T + tol && hist[k][0] <= (c + 1) * T + tol) {
        best = PetscMax(best, hist[k][1]);
        rows++;
      }
    /* a whole cycle, followed from its probe time on */
    if (rows && (c + 1) * T <= t_end + tol && hist[0][0] <= c * T + 0.25 * T + tol)
      peaks[n_cycles++] = best;
  }
  return n_cycles;
}
