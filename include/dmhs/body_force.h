/* Body accelerations on the liquid: a constant vector F, optionally pulsatile
 * F sin(2 pi t / T), plus gravity -g e_y. */
#ifndef DMHS_BODY_FORCE_H
#define DMHS_BODY_FORCE_H
#include "dmhs/module.h"

PetscErrorCode body_force_module_create(module **m);
/* The scene's default before the options pass (e.g. Poiseuille's driving force). */
PetscErrorCode body_force_set_default(module *m, double fx, double fy);
/* The scene's default gravity g [m/s^2] along -y (0 unless set). */
PetscErrorCode body_force_set_default_gravity(module *m, double g);
/* The scene's default period T of F sin(2 pi t/T) (0 = constant). */
PetscErrorCode body_force_set_default_period(module *m, double period);
/* The drive as set by the options (after the options pass): F = (Fx, Fy) [m/s^2] and the
 * period T [s] of F sin(2 pi t/T), 0 when constant. Either pointer may be NULL. */
PetscErrorCode body_force_get(module *m, double F[2], double *period);
/* a_body [m/s^2] at the time of the current force evaluation (its prepare phase). */
void body_force_current(const module *m, double a[2]);
/* The largest |a_body| over time, |(Fx, |Fy| + g)| [m/s^2]: the SPH module's time-step
 * limit on it (its particles' force criterion, 0.25 sqrt(h_s/|a|)). */
double body_force_peak(const module *m);
/* a_body [m/s^2] at time t (after the options pass). */
void body_force_at(const module *m, double t, double a[2]);

#endif
