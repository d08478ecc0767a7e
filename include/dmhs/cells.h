/* Link cells over owned + ghost particles (counting sort by cell) and the pair
 * list built from the half neighbour-cell stencil. */
#ifndef DMHS_CELLS_H
#define DMHS_CELLS_H
#include <petscsys.h>
#include <math.h>
#include "dmhs/particles.h"

typedef struct cells {
  double lo[DMHS_DIM]; /* lower corner of the covered region (box minus ghost width) */
  double size;         /* cell edge >= cutoff */
  PetscInt n[DMHS_DIM];
  PetscInt *start;    /* n cells + 1 offsets into order */
  PetscInt *order;    /* particle indices sorted by cell */
  PetscInt *position; /* per row, its position in order: which of a pair's rows comes first */
  PetscInt n_alloc_cells, n_alloc_particles;
  double (*xs)[DMHS_DIM]; /* positions in cell order (scratch) */
  unsigned char *flag;    /* per sorted row: 1 = ghost, 2 = wall, 4 = not liquid (scratch) */
  /* Per sorted row a, its candidates as two contiguous runs of the cell order: the own
   * cell after a and the E cell, [a + 1, run_end1[a]), and the NW, N and NE cells,
   * [run_first2[a], run_last2[a]). Rows are sorted by x within a cell, so each run is in
   * x order and keeps only the rows that can lie within the cutoff: x < x_a + cutoff in
   * the first; in the second |x - x_a| < sqrt(cutoff^2 - dy^2), dy the height of the
   * upper cells' lower edge above a (an empty run, 0 and 0, when dy >= cutoff). */
  PetscInt *run_end1, *run_first2, *run_last2;
  PetscInt n_alloc_sorted;
  /* The cell order as segments of consecutive rows: positions [seg_pos[s], seg_pos[s + 1])
   * hold rows seg_row[s], seg_row[s] + 1, ... A segment is all owned or all ghost. The owned
   * rows are sorted into cell order at the build (cells_sort.c), so they form a few long
   * segments between the ghosts: a copy into cell order (or back) streams through them. */
  PetscInt n_seg, n_alloc_seg;
  PetscInt *seg_pos, *seg_row;
  /* Pair list: pairs (i, j) with |x_i - x_j| < cutoff, at least one of them owned. */
  PetscInt n_pairs, n_alloc_pairs;
  PetscBool no_pair_list; /* every reader walks the cells: sort and flag only, list no pairs */
  PetscInt *pair_i, *pair_j;
  /* Counts the builds: a sweep that needs only a subset of the pairs (walls, repulsion)
   * keeps indices into the list, filtered once per build, valid while this matches. */
  PetscInt64 generation;
  /* Bonded pairs to leave out (solids; NULL = none): tested only for
   * pairs of two non-fluid particles, so the liquid's pairs pay nothing. */
  const struct topology *excl;
} cells;

/* The grid of cells_build_pairs over [lo, hi] for a cutoff: n cells per direction (edge >= cutoff)
 * and the inverse edges, and the cell of a position (outside the region: the edge cell). */
void cells_grid(const double lo[DMHS_DIM], const double hi[DMHS_DIM], double cutoff,
                PetscInt n[DMHS_DIM], double inv[DMHS_DIM]);
static inline PetscInt cells_locate(const double lo[DMHS_DIM], const double inv[DMHS_DIM],
                                    const PetscInt n[DMHS_DIM], const double x[DMHS_DIM]) {
  PetscInt ix = (PetscInt)floor((x[0] - lo[0]) * inv[0]);
  PetscInt iy = (PetscInt)floor((x[1] - lo[1]) * inv[1]);
  ix = PetscMin(PetscMax(ix, 0), n[0] - 1);
  iy = PetscMin(PetscMax(iy, 0), n[1] - 1);
  return iy * n[0] + ix;
}

/* The order within a cell: by x, then by global id. It depends on the positions and
 * ids only, not on which rows are owned or ghosts (bitwise rank-count invariance), and
 * x first lets the builds cut each candidate run by x (run_end1 ... above). A cell never
 * holds two rows with one gid: an image is a box length away. */
static inline PetscBool cells_row_before(const particles *ps, PetscInt i, PetscInt j) {
  const double xi = ps->x[i][0], xj = ps->x[j][0];
  return xi < xj || (xi == xj && ps->gid[i] < ps->gid[j]) ? PETSC_TRUE : PETSC_FALSE;
}

PetscErrorCode cells_create(cells *c);
PetscErrorCode cells_destroy(cells *c);
/* Sort particles [0, n_owned + n_ghost) into cells covering [lo, hi] and list every pair
 * closer than cutoff. Pairs of two ghosts, and pairs of two walls, are left out: nobody
 * owns the first, and walls do not act on each other. */
PetscErrorCode cells_build_pairs(cells *c, const particles *ps, const double lo[DMHS_DIM],
                                 const double hi[DMHS_DIM], double cutoff);

/* cells_sort.c: re-sorts the owned rows [0, n_owned) by the cell of the grid above, and by
 * x and then global id within a cell, moving every FIELD_MIGRATE field (ghosts must be empty). The
 * rows of a cell are then contiguous and in the order cells_build_pairs lists them, so the sweeps
 * read memory in order. */
PetscErrorCode cells_sort_owned_rows(particles *ps, const double lo[DMHS_DIM],
                                     const double hi[DMHS_DIM], double cutoff);

#endif
