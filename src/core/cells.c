/* Link cells by counting sort, and the pair list from the half stencil
 * (self, E, NW, N, NE) so each pair is found once. */
#include <math.h>
#include "dmhs/cells.h"
#include "dmhs/topology.h"

void cells_grid(const double lo[DMHS_DIM], const double hi[DMHS_DIM], double cutoff,
                PetscInt n[DMHS_DIM], double inv[DMHS_DIM]) {
  for (int k = 0; k < DMHS_DIM; k++) {
    n[k] = PetscMax(1, (PetscInt)floor((hi[k] - lo[k]) / cutoff));
    inv[k] = n[k] / (hi[k] - lo[k]);
  }
}

PetscErrorCode cells_create(cells *c) {
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(c, sizeof(*c)));
  PetscFunctionReturn(0);
}

PetscErrorCode cells_destroy(cells *c) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree3(c->start, c->order, c->position));
  PetscCall(PetscFree2(c->pair_i, c->pair_j));
  PetscCall(PetscFree(c->xs));
  PetscCall(PetscFree(c->flag));
  PetscCall(PetscFree3(c->run_end1, c->run_first2, c->run_last2));
  PetscCall(PetscFree2(c->seg_pos, c->seg_row));
  PetscCall(PetscMemzero(c, sizeof(*c)));
  PetscFunctionReturn(0);
}

static PetscErrorCode cells_ensure(cells *c, PetscInt n_cells, PetscInt n_particles) {
  PetscFunctionBeginUser;
  if (n_cells + 1 > c->n_alloc_cells || n_particles > c->n_alloc_particles) {
    PetscCall(PetscFree3(c->start, c->order, c->position));
    c->n_alloc_cells = PetscMax(n_cells + 1, c->n_alloc_cells);
    c->n_alloc_particles = PetscMax(n_particles + n_particles / 4, c->n_alloc_particles);
    PetscCall(PetscMalloc3(c->n_alloc_cells, &c->start, c->n_alloc_particles, &c->order,
                           c->n_alloc_particles, &c->position));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode cells_grow_pairs(cells *c) {
  PetscFunctionBeginUser;
  {
    PetscInt grown = PetscMax(1024, 2 * c->n_alloc_pairs);
    PetscInt *pi, *pj;
    PetscCall(PetscMalloc2(grown, &pi, grown, &pj));
    if (c->n_pairs) {
      PetscCall(PetscArraycpy(pi, c->pair_i, c->n_pairs));
      PetscCall(PetscArraycpy(pj, c->pair_j, c->n_pairs));
    }
    PetscCall(PetscFree2(c->pair_i, c->pair_j));
    c->pair_i = pi;
    c->pair_j = pj;
    c->n_alloc_pairs = grown;
  }
  PetscFunctionReturn(0);
}

/* First position in [first, last) whose x is past bound: x >= bound, or x > bound when
 * strict (rows in x order: a binary search). */
static inline PetscInt cells_first_past(const particles *ps, const PetscInt *order, PetscInt first,
                                        PetscInt last, double bound, PetscBool strict) {
  while (first < last) {
    const PetscInt mid = first + (last - first) / 2;
    const double x = ps->x[order[mid]][0];
    if (strict ? x > bound : x >= bound)
      last = mid;
    else
      first = mid + 1;
  }
  return first;
}

/* The candidate runs of every position (cells.h). Half the stencil (self, E, NW, N, NE)
 * lies in two stretches of the cell order: the own cell and E are consecutive, and so are
 * NW, N and NE; each stretch is in x order (rows by x within a cell, the cells left to
 * right). A partner is closer than the cutoff R: in the own cell and E only the rows with
 * x < x_a + R can be partners (a prefix). A row of the upper cells lies at least
 * dy = y_up - y_a above a (y_up: the upper row's lower edge; a cell is at least R
 * high), so only the rows with
 * |x - x_a| < sqrt(R^2 - dy^2) can be: one stretch found by two binary searches, empty
 * for a near the bottom of its cell. Cut at the build's positions with the build's cutoff,
 * the runs hold every pair of the list, and every pair a sweep finds until the next build
 * (no particle moves half the skin before it). */
static void cells_cut_runs(cells *c, const particles *ps, double inv_height) {
  const PetscInt n0 = c->n[0], n1 = c->n[1];
  const PetscInt *start = c->start, *order = c->order;
  /* margins far above round-off: a row cut off fails the pair test by a wide enough
   * margin that the list is exactly the one an uncut search finds (a row placed in the
   * upper cells lies above y_up but for the round-off of cells_locate) */
  const double cut = c->size * (1.0 + 1e-9), dy_margin = 1e-9 * c->size;
  for (PetscInt cy = 0; cy < n1; cy++) {
    const double y_up = c->lo[1] + (double)(cy + 1) / inv_height; /* cells_locate's edge */
    for (PetscInt cx = 0; cx < n0; cx++) {
      const PetscInt cell = cy * n0 + cx, up = (cy + 1) * n0 + cx;
      const PetscBool has_e = cx + 1 < n0, has_up = cy + 1 < n1;
      const PetscInt end1 = has_e ? start[cell + 2] : start[cell + 1];
      const PetscInt first_up = has_up && cx > 0 ? start[up - 1] : (has_up ? start[up] : 0);
      const PetscInt end_up = has_up ? (cx + 1 < n0 ? start[up + 2] : start[up + 1]) : 0;
      for (PetscInt a = start[cell]; a < start[cell + 1]; a++) {
        const double xa = ps->x[order[a]][0], ya = ps->x[order[a]][1];
        c->run_end1[a] = cells_first_past(ps, order, a + 1, end1, xa + cut, PETSC_FALSE);
        const double dy = PetscMax(y_up - ya - dy_margin, 0.0);
        if (!has_up || dy >= cut) {
          c->run_first2[a] = c->run_last2[a] = 0;
          continue;
        }
        const double half_width = sqrt(cut * cut - dy * dy);
        c->run_first2[a] =
            cells_first_past(ps, order, first_up, end_up, xa - half_width, PETSC_TRUE);
        c->run_last2[a] =
            cells_first_past(ps, order, c->run_first2[a], end_up, xa + half_width, PETSC_FALSE);
      }
    }
  }
}

/* The segments of consecutive rows in the cell order (cells.h), split where the owned rows
 * end so that a segment is all owned or all ghost. */
static inline PetscBool cells_segment_starts(const PetscInt *order, PetscInt a, PetscInt n_owned) {
  return a == 0 || order[a] != order[a - 1] + 1 || order[a] == n_owned ? PETSC_TRUE : PETSC_FALSE;
}

static PetscErrorCode cells_find_segments(cells *c, PetscInt n, PetscInt n_owned) {
  const PetscInt *order = c->order;
  PetscFunctionBeginUser;
  PetscInt n_seg = 0;
  for (PetscInt a = 0; a < n; a++)
    n_seg += cells_segment_starts(order, a, n_owned);
  if (n_seg + 1 > c->n_alloc_seg) {
    PetscCall(PetscFree2(c->seg_pos, c->seg_row));
    c->n_alloc_seg = n_seg + n_seg / 4 + 1;
    PetscCall(PetscMalloc2(c->n_alloc_seg, &c->seg_pos, c->n_alloc_seg, &c->seg_row));
  }
  PetscInt s = 0;
  for (PetscInt a = 0; a < n; a++)
    if (cells_segment_starts(order, a, n_owned)) {
      c->seg_pos[s] = a;
      c->seg_row[s++] = order[a];
    }
  c->seg_pos[n_seg] = n;
  c->n_seg = n_seg;
  PetscFunctionReturn(0);
}

PetscErrorCode cells_build_pairs(cells *c, const particles *ps, const double lo[DMHS_DIM],
                                 const double hi[DMHS_DIM], double cutoff) {
  const PetscInt n = ps->n_owned + ps->n_ghost;
  PetscFunctionBeginUser;
  PetscCheck(cutoff > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "cells: cutoff must be > 0");
  c->size = cutoff;
  double inv[DMHS_DIM];
  cells_grid(lo, hi, cutoff, c->n, inv);
  const PetscInt n_cells = c->n[0] * c->n[1];
  for (int k = 0; k < DMHS_DIM; k++)
    c->lo[k] = lo[k];
  PetscCall(cells_ensure(c, n_cells, n));

  /* counting sort by cell; positions outside the covered region clamp to edge cells.
   * position[] holds each row's cell until the order is known (one array fewer a row) */
  PetscInt *cell_of = c->position;
  PetscCall(PetscArrayzero(c->start, n_cells + 1));
  for (PetscInt i = 0; i < n; i++) {
    cell_of[i] = cells_locate(lo, inv, c->n, ps->x[i]);
    c->start[cell_of[i] + 1]++;
  }
  for (PetscInt k = 0; k < n_cells; k++)
    c->start[k + 1] += c->start[k];
  {
    PetscInt *fill;
    PetscCall(PetscMalloc1(n_cells, &fill));
    PetscCall(PetscArraycpy(fill, c->start, n_cells));
    for (PetscInt i = 0; i < n; i++)
      c->order[fill[cell_of[i]]++] = i;
    PetscCall(PetscFree(fill));
  }
  /* mpi: within a cell, order by x and global id (cells_row_before). The pairs of a
   * particle are then listed, and its sums accumulated, in an order that does not depend
   * on which rows are owned or ghosts, i.e. on the rank count: with the exactly
   * antisymmetric pair terms the run is bitwise the same on 1..N ranks. */
  for (PetscInt k = 0; k < n_cells; k++)
    for (PetscInt a = c->start[k] + 1; a < c->start[k + 1]; a++) {
      const PetscInt row = c->order[a];
      PetscInt b = a;
      for (; b > c->start[k] && cells_row_before(ps, row, c->order[b - 1]); b--)
        c->order[b] = c->order[b - 1];
      c->order[b] = row;
    }
  for (PetscInt a = 0; a < n; a++)
    c->position[c->order[a]] = a;

  /* positions and flags gathered in cell order: the search below then walks
   * contiguous memory instead of jumping through order[] */
  if (n > c->n_alloc_sorted || (!c->no_pair_list && !c->xs)) {
    PetscCall(PetscFree(c->xs));
    PetscCall(PetscFree(c->flag));
    PetscCall(PetscFree3(c->run_end1, c->run_first2, c->run_last2));
    c->n_alloc_sorted = n + n / 4;
    PetscCall(PetscMalloc1(c->n_alloc_sorted, &c->flag));
    PetscCall(PetscMalloc3(c->n_alloc_sorted, &c->run_end1, c->n_alloc_sorted, &c->run_first2,
                           c->n_alloc_sorted, &c->run_last2));
    if (!c->no_pair_list) /* the positions in cell order serve only the pair search */
      PetscCall(PetscMalloc1(c->n_alloc_sorted, &c->xs));
  }
  const PetscInt n_owned = ps->n_owned;
  const struct topology *bonded = c->excl; /* its slot[]: which rows have exclusions */
  for (PetscInt a = 0; a < n; a++) {
    const PetscInt i = c->order[a];
    if (c->xs) {
      c->xs[a][0] = ps->x[i][0];
      c->xs[a][1] = ps->x[i][1];
    }
    c->flag[a] = (i >= n_owned ? 1 : 0) | (ps->type[i] == PTYPE_WALL ? 2 : 0) |
                 (bonded && bonded->slot[i] >= 0 ? 4 : 0);
  }

  cells_cut_runs(c, ps, inv[1]);
  PetscCall(cells_find_segments(c, n, n_owned));

  c->n_pairs = 0;
  c->generation++;
  if (c->no_pair_list)
    PetscFunctionReturn(0);
  const double cut2 = cutoff * cutoff;
  const double(*restrict xs)[2] = (const double(*)[2])c->xs;
  const unsigned char *restrict flag = c->flag;
  const struct topology *excl = c->excl;
  for (PetscInt a = 0; a < n; a++) {
    const double xa = xs[a][0], ya = xs[a][1];
    const unsigned fa = flag[a];
    /* the half stencil's two runs: each unordered pair is visited once */
    const PetscInt first[2] = {a + 1, c->run_first2[a]},
                   last[2] = {c->run_end1[a], c->run_last2[a]};
    for (int run = 0; run < 2; run++)
      for (PetscInt b = first[run]; b < last[run]; b++) {
        const double dx = xa - xs[b][0], dy = ya - xs[b][1];
        if (dx * dx + dy * dy >= cut2)
          continue;
        /* nobody owns a ghost-ghost pair; walls do not act on each other */
        const unsigned both = fa & flag[b];
        if (both & 3)
          continue;
        const PetscInt i = c->order[a], j = c->order[b];
        /* bonded 1-2 / 1-3 partners (LAMMPS special_bonds 0 0 1 angle yes): only between two
         * bonded particles, so liquid pairs never pay for the lookup */
        if ((both & 4) && excl && topology_excluded(excl, ps, i, j))
          continue;
        if (c->n_pairs == c->n_alloc_pairs)
          PetscCall(cells_grow_pairs(c));
        c->pair_i[c->n_pairs] = PetscMin(i, j);
        c->pair_j[c->n_pairs] = PetscMax(i, j);
        c->n_pairs++;
      }
  }
  PetscFunctionReturn(0);
}
