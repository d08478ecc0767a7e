/* Module wall_wave: walls that move transversely as a travelling sine wave, the
 * prescribed motion of a peristaltic channel. Every wall particle keeps its x and
 * its rest position x0 (the flat channel of half-width a, field x0); at every force
 * evaluation, at that evaluation's time t (its prepare phase),
 *   y   = y0 + s b sin(2 pi (x0 - c t)/lambda),   s = sign(y0)
 *   v   = (0, -s b (2 pi c/lambda) cos(2 pi (x0 - c t)/lambda))
 * so each column of wall layers follows the surface y = +-(a + b sin(...)) rigidly;
 * with the to_surface field (the quadratic wall extrapolation) also each particle's
 * vector to the moved surface. */
#ifndef DMHS_WALL_WAVE_H
#define DMHS_WALL_WAVE_H
#include "dmhs/module.h"

PetscErrorCode wall_wave_module_create(module **m);
/* The wave: half-width a [m] of the walls' mean position (their surfaces at rest are
 * y = +-a), amplitude b [m], wavelength lambda [m], wave speed c [m/s] along +x.
 * Call before the module's options pass. */
PetscErrorCode wall_wave_set(module *m, double a, double b, double lambda, double c);

#endif
