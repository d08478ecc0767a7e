/* Inside io: the checkpoint's checksummed row datasets and its groups (checkpoint_rows.c),
 * used by the particles' part (checkpoint.c) and the topology's (topology_checkpoint.c). */
#ifndef DMHS_IO_CHECKPOINT_ROWS_H
#define DMHS_IO_CHECKPOINT_ROWS_H
#include <hdf5.h>
#include <petscsys.h>
#include "dmhs/fields.h"

/* h5io_write_rows (native width), then the dataset's checksum. Collective. */
PetscErrorCode checkpoint_write_rows(MPI_Comm comm, const char *path, hid_t loc,
                                     const field_desc *f, const void *data, PetscInt n_local,
                                     PetscInt64 offset, PetscInt64 n);
/* h5io_read_rows, then the checksum: reduce when the rows are split over the ranks
 * (collective then), not when every rank read them all. `where` names the group. */
PetscErrorCode checkpoint_read_rows(MPI_Comm comm, const char *path, hid_t loc, const char *where,
                                    const field_desc *f, void *data, PetscInt n_local,
                                    PetscInt64 offset, PetscInt64 n, PetscBool reduce);
/* Rows already read against the dataset's checksum (the second half of
 * checkpoint_read_rows, for a reader that checks something else in between). */
PetscErrorCode checkpoint_verify(MPI_Comm comm, const char *path, hid_t loc, const char *where,
                                 const field_desc *f, const void *data, PetscInt n_local,
                                 PetscInt64 offset, PetscBool reduce);

/* Opens group `name` under loc, or fails naming what is missing (`what`). */
PetscErrorCode checkpoint_open_group(const char *path, hid_t loc, const char *name,
                                     const char *what, hid_t *grp);

#endif
