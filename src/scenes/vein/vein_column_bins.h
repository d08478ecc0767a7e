/* The column mid-points of one vein leaflet binned on a grid of 4 dx, for the crossing check
 * (vein_crossings.c): which column is nearest to a point. A point beside a column (within dx
 * along it and 3 dx across) is within sqrt(10) dx of the column's mid-point, so every column
 * that can matter lies in the 3 x 3 bins around the point: the search visits a few columns
 * instead of every column of the leaflet. Mid-points are kept relative to the leaflet's box
 * centre (the minimum image), as the points are. */
#ifndef DMHS_VEIN_COLUMN_BINS_H
#define DMHS_VEIN_COLUMN_BINS_H
#include "vein_leaflets.h"

typedef struct column_bins {
  double lo[2], inv_bin;
  PetscInt nb[2];
  PetscInt *first;  /* nb[0] nb[1] + 1 offsets into col */
  PetscInt *col;    /* the columns, bin by bin, ascending within a bin */
  double (*mid)[2]; /* per column, relative to the box centre */
  PetscInt n_bins_alloc, n_cols_alloc;
} column_bins;

/* Bins the column mid-points of leaflet w (v's gathered positions) over its box: centre
 * box[0..1], half-widths box[2..3], which reach at least 4 dx beyond the leaflet. Reuses b's
 * arrays (zero-initialise b before the first build). */
PetscErrorCode column_bins_build(column_bins *b, const vein_leaflets *v, const domain *dom, int w,
                                 const double box[4]);
/* The column whose mid-point is nearest to d (relative to the box centre, inside the box),
 * the lowest index on a tie; -1 when none is within sqrt(10) dx, where no column can have
 * the point beside it. */
PetscInt column_bins_nearest(const column_bins *b, const double d[2], double dx);
PetscErrorCode column_bins_destroy(column_bins *b);

#endif
