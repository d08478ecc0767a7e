/* Collecting per-rank rows of doubles on rank 0, for the few outputs a
 * single process writes (profiles, final dumps, diagnostics CSVs). */
#ifndef DMHS_GATHER_H
#define DMHS_GATHER_H
#include <petscsys.h>

/* Every rank passes its block of n_mine doubles; on rank 0, *all (free with
 * PetscFree) receives the blocks in rank order and *n_all their total length;
 * elsewhere *all = NULL and *n_all = 0. Collective. */
PetscErrorCode gather_to_root(MPI_Comm comm, const double *mine, size_t n_mine, double **all,
                              size_t *n_all);

#endif
