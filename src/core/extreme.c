/* The largest value over the ranks with its particle's gid, ties to the lowest gid (see
 * extreme.h): every rank's candidate on every rank, taken in rank order by the same rule,
 * so every rank holds the same answer. */
#include "dmhs/extreme.h"

PetscErrorCode extreme_max(MPI_Comm comm, extreme_value mine, extreme_value *best) {
  PetscMPIInt size;
  extreme_value *all;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscMalloc1(size, &all));
  PetscCallMPI(MPI_Allgather(&mine, (PetscMPIInt)sizeof(mine), MPI_BYTE, all,
                             (PetscMPIInt)sizeof(mine), MPI_BYTE, comm));
  *best = EXTREME_NONE;
  for (PetscMPIInt r = 0; r < size; r++)
    if (all[r].gid >= 0)
      extreme_consider(best, all[r].value, all[r].gid);
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}
