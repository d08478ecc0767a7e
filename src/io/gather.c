/* Rows of doubles from every rank to rank 0 (MPI_Gatherv), see gather.h. */
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
