/* Domain decomposition: a coarse grid of cells over the box (edge >= the ghost
 * width), each cell owned by one rank. Rank 0 partitions the cell graph,
 * weighted by work (particles and their bonded partners), with METIS and broadcasts the owner of
 * every cell, so that all ranks agree bit for bit. Repartitions when the load imbalance (max/mean
 * owned work: particles + bonded partners) passes a threshold. partition.c is the only file that
 * calls METIS. */
#ifndef DMHS_PARTITION_H
#define DMHS_PARTITION_H
#include <math.h>
#include <petscsys.h>
#include "dmhs/particles.h"

struct sim;

typedef struct partition {
  PetscInt nc[DMHS_DIM]; /* coarse cells per axis */
  double lo[DMHS_DIM];   /* box lower corner */
  double edge[DMHS_DIM]; /* cell edge along each axis (>= ghost width) */
  double inv_edge[DMHS_DIM];
  PetscInt n_cells;
  PetscMPIInt *owner; /* rank owning each cell, row-major (iy * nc[0] + ix) */
  char *frontier;     /* this rank's cells with a neighbour owned elsewhere or across a
                         periodic boundary: only their particles can be ghosts anywhere */
  /* options */
  double imbalance_max; /* -partition_imbalance: repartition above this max/mean */
  PetscBool quiet;      /* no "repartitioned" line (the driver's -quiet) */
  PetscInt interval;    /* -partition_interval: steps between imbalance checks (0 = never) */
  /* state */
  double imbalance; /* max/mean owned work (particles + bonded partners) at the last check */
  PetscInt n_repartitions;
  PetscInt64 edge_cut; /* METIS objective (cut edges) of the current partition */
} partition;

/* Reads -partition_imbalance and -partition_interval. */
PetscErrorCode partition_set_from_options(partition *p, struct sim *s);
/* Lays the coarse grid over s->dom with edge >= s->hal.width, partitions it by
 * the particles the scene built (every rank built the same full set) and keeps
 * on each rank only the particles in its cells. */
PetscErrorCode partition_setup(partition *p, struct sim *s);
PetscErrorCode partition_destroy(partition *p);
/* Every -partition_interval steps: measures the imbalance and, above the
 * threshold, recomputes the owners (particles then move in migrate). */
PetscErrorCode partition_check(partition *p, struct sim *s);
/* Recomputes the owners of all cells from the current particle counts. */
PetscErrorCode partition_compute(partition *p, struct sim *s);
/* Measures max/mean of owned counts over ranks (collective). */
PetscErrorCode partition_measure_imbalance(partition *p, struct sim *s);

/* Coarse cell of a (wrapped) position; positions on or outside the box edge clamp. */
static inline PetscInt partition_cell_of(const partition *p, const double x[DMHS_DIM]) {
  PetscInt c[DMHS_DIM];
  for (int k = 0; k < DMHS_DIM; k++) {
    c[k] = (PetscInt)floor((x[k] - p->lo[k]) * p->inv_edge[k]);
    c[k] = c[k] < 0 ? 0 : c[k] >= p->nc[k] ? p->nc[k] - 1 : c[k];
  }
  return c[1] * p->nc[0] + c[0];
}

#endif
