/* The diagnostic "peristaltic_flux" (src/scenes/peristaltic_channel/peristaltic_flux.c): the
 * time-mean volume flux of the peristaltic channel over every completed wave period T, against the
 * long-wavelength, low-Reynolds-number theory (analytic.h). At every step (step 0 included) it
 * measures the lab-frame flux per unit depth Q(t) = (sum over liquid particles j of V_j v_x,j) /
 * lambda,  V_j = m_j/rho_j and integrates it in time by the trapezoid rule, the step that crosses a
 * period's end split there by linear interpolation, so that every mean is over exactly
 * [(k-1) T, k T]. <output_dir>/flux.csv: cycle,t,Q_mean,Q_theory, one row per
 * completed period (t its end [s], fluxes [m^2/s]); a restart continues the running
 * mean and the file exactly. At the end of the run, a line comparing the last
 * period's mean with the theory, and the liquid's largest density deviation and
 * Mach number over the run. */
#ifndef DMHS_PERISTALTIC_FLUX_H
#define DMHS_PERISTALTIC_FLUX_H
#include "dmhs/sim.h"

typedef struct peristaltic_flux_layout {
  double a, b;   /* the walls' mean half-width and the wave's amplitude [m] */
  double lambda; /* wavelength = the x period of the channel [m] */
  double c;      /* wave speed [m/s], > 0 */
} peristaltic_flux_layout;

PetscErrorCode peristaltic_flux_register(sim *s, const peristaltic_flux_layout *lay);

#endif
