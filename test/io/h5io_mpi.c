/* Parallel HDF5 rows on several ranks with uneven (and empty) row counts:
 * each rank writes its rows as a hyperslab at the exclusive prefix sum of the
 * counts, then every rank reads back a different split and checks each value
 * against its global row index. Run: mpirun -n 3 h5io_mpi <dir>. */
#include <petscsys.h>
#include "dmhs/fields.h"
#include "io/h5io.h"

int main(int argc, char **argv) {
  PetscMPIInt rank, size;
  PetscInt64 offset, n_global;
  char path[PETSC_MAX_PATH_LEN];
  hid_t fid;
  const field_desc fx = {"x", 2, FIELD_REAL, 0, 0, "m"},
                   fid_desc = {"gid", 1, FIELD_INT64, 0, 0, "1"};
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCheck(argc > 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "usage: h5io_mpi <dir>");
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/rows.h5", argv[1]));

  /* rank r owns 2r + 3 rows, except rank 1, which owns none */
  const PetscInt n = rank == 1 ? 0 : 2 * rank + 3;
  double(*x)[2];
  PetscInt64 *gid;
  PetscCall(h5io_offsets(PETSC_COMM_WORLD, n, &offset, &n_global));
  PetscCall(PetscMalloc2(n + 1, &x, n + 1, &gid));
  for (PetscInt i = 0; i < n; i++) {
    gid[i] = offset + i;
    x[i][0] = 0.5 * (double)gid[i];
    x[i][1] = -1.0 * (double)gid[i];
  }
  PetscCall(h5io_create(PETSC_COMM_WORLD, path, &fid));
  PetscCall(h5io_write_rows(PETSC_COMM_WORLD, path, fid, &fx, x, n, offset, n_global, 3));
  PetscCall(h5io_write_rows(PETSC_COMM_WORLD, path, fid, &fid_desc, gid, n, offset, n_global, 1));
  PetscCall(h5io_close(path, &fid));
  PetscCall(PetscFree2(x, gid));

  /* read back an even split of the ids */
  const PetscInt m = (PetscInt)(n_global / size + (rank < n_global % size ? 1 : 0));
  PetscInt64 *back;
  PetscCall(h5io_offsets(PETSC_COMM_WORLD, m, &offset, &n_global));
  PetscCall(PetscMalloc1(m + 1, &back));
  PetscCall(h5io_open(PETSC_COMM_WORLD, path, &fid));
  PetscCall(h5io_read_rows(PETSC_COMM_WORLD, path, fid, &fid_desc, back, m, offset, n_global));
  PetscCall(h5io_close(path, &fid));
  for (PetscInt i = 0; i < m; i++)
    PetscCheck(back[i] == offset + i, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "rank %d row %" PetscInt_FMT ": %" PetscInt64_FMT, rank, i, back[i]);
  PetscCall(PetscFree(back));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                        "h5io on %d ranks: %" PetscInt64_FMT " rows written and read back: OK\n",
                        size, n_global));
  PetscCall(PetscFinalize());
  return 0;
}
