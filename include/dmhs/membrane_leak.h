/* Liquid that went through a membrane. A membrane laid out as columns of
 * bonded particles (gid = g0 + column * layers + layer, columns ordered along
 * x) separates the liquid above it from the empty space below; a fluid
 * particle found below the polyline through one layer's particles, inside
 * the membrane's x range, has gone through that layer. */
#ifndef DMHS_MEMBRANE_LEAK_H
#define DMHS_MEMBRANE_LEAK_H
#include "dmhs/sim.h"

typedef struct {
  PetscInt64 g0;      /* gid of column 0, layer 0 */
  PetscInt n_columns; /* columns along x */
  PetscInt layers;    /* particles per column, 0 = the top (liquid side) */
} membrane_layout;

/* Fluid particles over all ranks lodged in the membrane (below its top
 * layer's polyline, above its bottom layer's) and through it (below the
 * bottom layer's). Collective. */
PetscErrorCode membrane_leak_count(sim *s, const membrane_layout *m, PetscInt64 *n_inside,
                                   PetscInt64 *n_through);

#endif
