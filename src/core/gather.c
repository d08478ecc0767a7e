/* Blocks from every rank: rows of doubles to rank 0 (MPI_Gatherv) and items of
 * any size to every rank (MPI_Allgatherv of bytes), see gather.h. */
#include <limits.h>
#include "dmhs/gather.h"

PetscErrorCode gather_to_root(MPI_Comm comm, const double *mine, size_t n_mine, double **all,
                              size_t *n_all) {
  PetscMPIInt rank, size, count, *counts = NULL, *displs = NULL;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCheck(n_mine < INT_MAX, PETSC_COMM_SELF, PETSC_ERR_SUP,
             "gather_to_root: %zu values exceed an MPI count", n_mine);
  count = (PetscMPIInt)n_mine;
  *all = NULL;
  *n_all = 0;
  if (rank == 0)
    PetscCall(PetscMalloc2(size, &counts, size + 1, &displs));
  PetscCallMPI(MPI_Gather(&count, 1, MPI_INT, counts, 1, MPI_INT, 0, comm));
  if (rank == 0) {
    size_t total = 0;
    displs[0] = 0;
    for (PetscMPIInt r = 0; r < size; r++) {
      total += (size_t)counts[r];
      PetscCheck(total < INT_MAX, PETSC_COMM_SELF, PETSC_ERR_SUP,
                 "gather_to_root: %zu values exceed an MPI count", total);
      displs[r + 1] = (PetscMPIInt)total;
    }
    PetscCall(PetscMalloc1(total + 1, all));
    *n_all = total;
  }
  PetscCallMPI(MPI_Gatherv(mine, count, MPI_DOUBLE, *all, counts, displs, MPI_DOUBLE, 0, comm));
  PetscCall(PetscFree2(counts, displs));
  PetscFunctionReturn(0);
}

PetscErrorCode gather_all(MPI_Comm comm, const char *what, const void *mine, size_t n_mine,
                          size_t item_size, void *all, size_t *n_all, size_t *start) {
  PetscMPIInt rank, size, *counts, *displs;
  PetscInt64 *items, total = 0;
  const PetscInt64 my_items = (PetscInt64)n_mine, most = (INT_MAX - 1) / (PetscInt64)item_size;
  void **out = (void **)all;
  PetscFunctionBeginUser;
  PetscCheck(item_size > 0 && item_size < INT_MAX, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE,
             "gather_all (%s): items of %zu bytes", what, item_size);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  /* the counts travel as 64-bit integers, so that every rank sees every rank's count and
   * refuses an overflow with the others (none is left waiting in the gather) */
  PetscCall(PetscMalloc3(size, &items, size, &counts, size + 1, &displs));
  PetscCallMPI(MPI_Allgather(&my_items, 1, MPIU_INT64, items, 1, MPIU_INT64, comm));
  displs[0] = 0;
  for (PetscMPIInt r = 0; r < size; r++) {
    PetscCheck(items[r] <= most, comm, PETSC_ERR_SUP,
               "gather_all (%s): %" PetscInt64_FMT " items of %zu bytes on rank %d exceed an MPI "
               "count (%d bytes)",
               what, items[r], item_size, (int)r, INT_MAX);
    total += items[r] * (PetscInt64)item_size;
    PetscCheck(total < INT_MAX, comm, PETSC_ERR_SUP,
               "gather_all (%s): the items of ranks 0 to %d (%" PetscInt64_FMT " bytes) exceed an "
               "MPI count (%d bytes)",
               what, (int)r, total, INT_MAX);
    counts[r] = (PetscMPIInt)(items[r] * (PetscInt64)item_size);
    displs[r + 1] = (PetscMPIInt)total;
  }
  PetscCall(PetscMalloc((size_t)total + item_size, out));
  PetscCallMPI(MPI_Allgatherv(mine, counts[rank], MPI_BYTE, *out, counts, displs, MPI_BYTE, comm));
  *n_all = (size_t)total / item_size;
  if (start)
    *start = (size_t)displs[rank] / item_size;
  PetscCall(PetscFree3(items, counts, displs));
  PetscFunctionReturn(0);
}
