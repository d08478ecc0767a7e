/* Module angle_harmonic: U = k_a (theta - theta0)^2 per angle i-j-k (centre j),
 * k_a [J] and theta0 [deg] per angle type (-angle_k, -angle_theta0). */
#ifndef DMHS_ANGLE_HARMONIC_H
#define DMHS_ANGLE_HARMONIC_H
#include "dmhs/module.h"

struct sim;

PetscErrorCode angle_harmonic_module_create(module **m);
/* The scene's defaults for every angle type; after solid_modules_enable. */
PetscErrorCode angle_set_default(struct sim *s, double k, double theta0_deg);
/* Resolved k_a [J] and theta0 [rad] of type 0 (for scenes' diagnostics). */
PetscErrorCode angle_get_params(struct sim *s, double *k, double *theta0);

#endif
