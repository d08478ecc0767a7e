/* Module repulsion: the no-penetration force between solid/wall particles and
 * fluid particles, f = K [(r* / r)^p1 - (r* / r)^p2] r_vec/r^2 for r < r* (doc/theory.md). */
#ifndef DMHS_REPULSION_H
#define DMHS_REPULSION_H
#include "dmhs/module.h"

PetscErrorCode repulsion_module_create(module **m);
/* The scene's defaults (before the options pass): K [J], r* [m], exponents. */
PetscErrorCode repulsion_set_default(module *m, double K, double rstar, PetscInt p1, PetscInt p2);
/* The scene's default for -repulsion_bodies (needs the optional `body` field). */
PetscErrorCode repulsion_set_bodies(module *m, PetscBool on);

#endif
