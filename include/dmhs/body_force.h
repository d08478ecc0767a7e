/* Body accelerations on the liquid: a constant vector F, optionally pulsatile
 * F sin(2 pi t / T), plus gravity -g e_y. */
#ifndef DMHS_BODY_FORCE_H
#define DMHS_BODY_FORCE_H
#include "dmhs/module.h"

PetscErrorCode body_force_module_create(module **m);
/* The scene's default before the options pass (e.g. Poiseuille's driving force). */
PetscErrorCode body_force_set_default(module *m, double fx, double fy);
/* The scene's default period T of F sin(2 pi t/T) (0 = constant). */
PetscErrorCode body_force_set_default_period(module *m, double period);
/* The resolved drive F and period T (after the options pass). */
PetscErrorCode body_force_get_drive(module *m, double F[], double *period);

#endif
