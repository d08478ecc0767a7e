/* Collecting per-rank blocks: rows of doubles on rank 0, for the few outputs a
 * single process writes (profiles, final dumps, diagnostics CSVs), and blocks
 * of any fixed-size item on every rank, for the collective decisions every
 * rank takes the same way (clot events, topology changes, the halo check, the
 * snapshot's bond rows). */
#ifndef DMHS_GATHER_H
#define DMHS_GATHER_H
#include <petscsys.h>

/* Every rank passes its block of n_mine doubles; on rank 0, *all (free with
 * PetscFree) receives the blocks in rank order and *n_all their total length;
 * elsewhere *all = NULL and *n_all = 0. Collective. */
PetscErrorCode gather_to_root(MPI_Comm comm, const double *mine, size_t n_mine, double **all,
                              size_t *n_all);

/* Every rank passes n_mine items of item_size bytes each; on every rank, *all (a pointer
 * to a pointer of the item's type; free with PetscFree; never NULL, room for one item
 * more) receives every rank's items in rank order, as bytes (MPI_Allgatherv of
 * MPI_BYTE), *n_all their count and, when start is not NULL, *start the index of this
 * rank's first item in *all. An error on every rank, naming `what` (what the items are,
 * for the message), when the bytes of one rank or of all ranks exceed an MPI count
 * (INT_MAX). Collective. */
PetscErrorCode gather_all(MPI_Comm comm, const char *what, const void *mine, size_t n_mine,
                          size_t item_size, void *all, size_t *n_all, size_t *start);

#endif
