/* Owned rows re-sorted by cell at every neighbour build, so that the rows the
 * sweeps visit together lie together in memory: the SPH sweep's copy into cell
 * order (sph_force_cells.c) then streams instead of jumping, and so do the
 * integration and every pair loop. The key is the cell of cells_build_pairs'
 * grid and, within a cell, x and then the global id (cells_row_before): the order depends on the
 * positions and ids only, not on where the rows were before (a restart, or the arrival order of
 * migrated particles, ends in the same rows). No row index survives a build anyway: migration
 * renumbers rows on several ranks, and everything kept across steps is a FIELD_MIGRATE field or
 * keyed by global id. */
#include <string.h>
#include "dmhs/cells.h"
#include "dmhs/fields.h"

#define SORT_MAX_FIELDS 32

PetscErrorCode cells_sort_owned_rows(particles *ps, const double lo[DMHS_DIM],
                                     const double hi[DMHS_DIM], double cutoff) {
  const PetscInt n = ps->n_owned;
  PetscInt grid[DMHS_DIM];
  double inv[DMHS_DIM];
  PetscInt *cell, *start, *rows;
  PetscFunctionBeginUser;
  PetscCheck(ps->n_ghost == 0, PETSC_COMM_SELF, PETSC_ERR_ORDER,
             "cells_sort_owned_rows: ghosts must be cleared first");
  if (n < 2)
    PetscFunctionReturn(0);
  cells_grid(lo, hi, cutoff, grid, inv);
  const PetscInt n_cells = grid[0] * grid[1];
  PetscCall(PetscMalloc3(n, &cell, n_cells + 1, &start, n, &rows));
  PetscCall(PetscArrayzero(start, n_cells + 1));
  PetscBool sorted = PETSC_TRUE;
  for (PetscInt i = 0; i < n; i++) {
    cell[i] = cells_locate(lo, inv, grid, ps->x[i]);
    start[cell[i] + 1]++;
    if (i > 0 &&
        (cell[i] < cell[i - 1] || (cell[i] == cell[i - 1] && cells_row_before(ps, i, i - 1))))
      sorted = PETSC_FALSE;
  }
  if (!sorted) {
    for (PetscInt k = 0; k < n_cells; k++)
      start[k + 1] += start[k];
    for (PetscInt i = 0; i < n; i++) /* counting sort: stable, rows of a cell in row order */
      rows[start[cell[i]]++] = i;
    /* start[k] now ends cell k: within each cell, insertion sort by x and gid (few rows,
     * mostly in order already) */
    PetscInt first = 0;
    for (PetscInt k = 0; k < n_cells; k++) {
      for (PetscInt a = first + 1; a < start[k]; a++) {
        const PetscInt row = rows[a];
        PetscInt b = a;
        for (; b > first && cells_row_before(ps, row, rows[b - 1]); b--)
          rows[b] = rows[b - 1];
        rows[b] = row;
      }
      first = start[k];
    }
    /* move every field that travels with a particle, one field at a time through a buffer
     * of one field's rows: a copy of all fields at once would add their whole size to the
     * run's peak memory at every build */
    const field_desc *f[SORT_MAX_FIELDS];
    const int nf = particles_select_fields(FIELD_MIGRATE, f, SORT_MAX_FIELDS);
    size_t widest = 0;
    for (int k = 0; k < nf; k++)
      widest = PetscMax(widest, fields_row_bytes(f[k]));
    char *buf;
    PetscCall(PetscMalloc1(widest * (size_t)n, &buf));
    for (int k = 0; k < nf; k++) {
      const size_t row = fields_row_bytes(f[k]);
      char *base = *fields_member(ps, f[k]);
      for (PetscInt e = 0; e < n; e++)
        memcpy(buf + row * (size_t)e, base + row * (size_t)rows[e], row);
      memcpy(base, buf, row * (size_t)n);
    }
    PetscCall(PetscFree(buf));
  }
  PetscCall(PetscFree3(cell, start, rows));
  PetscFunctionReturn(0);
}
