/* Module solid_load: what the outside does to a solid in the validation
 * scenes: a point load F [N] shared equally by the particles whose load field
 * is SOLID_LOAD_MARK (e.g. a cantilever's tip; the field exists with this module), and viscous
 * damping -gamma v on solid particles (to reach a static state; LAMMPS fix viscous). */
#ifndef DMHS_SOLID_LOAD_H
#define DMHS_SOLID_LOAD_H
#include "dmhs/module.h"

#define SOLID_LOAD_MARK 1

PetscErrorCode solid_load_module_create(module **m);
/* Scene defaults: load Fx, Fy [N] (total per unit depth), damping gamma [1/s]. */
PetscErrorCode solid_load_set_default(module *m, double fx, double fy, double gamma);
/* The resolved load [N]. */
PetscErrorCode solid_load_get_force(module *m, double F[2]);
/* The resolved damping rate gamma [1/s]. */
PetscErrorCode solid_load_get_damping(module *m, double *gamma);

#endif
