/* Inside io: the checkpoint's checksummed row datasets (checkpoint.c), and the parts of
 * a checkpoint other files write (topology_checkpoint.c). */
#ifndef DMHS_IO_CHECKPOINT_ROWS_H
#define DMHS_IO_CHECKPOINT_ROWS_H
#include <hdf5.h>
#include <petscsys.h>
#include "dmhs/fields.h"

struct sim;

/* h5io_write_rows (native width), then the dataset's checksum. Collective. */
PetscErrorCode checkpoint_write_rows(MPI_Comm comm, const char *path, hid_t loc,
                                     const field_desc *f, const void *data, PetscInt n_local,
                                     PetscInt64 offset, PetscInt64 n);
/* h5io_read_rows, then the checksum: reduce when the rows are split over the ranks
 * (collective then), not when every rank read them all. `where` names the group. */
PetscErrorCode checkpoint_read_rows(MPI_Comm comm, const char *path, hid_t loc, const char *where,
                                    const field_desc *f, void *data, PetscInt n_local,
                                    PetscInt64 offset, PetscInt64 n, PetscBool reduce);

/* Opens group `name` under loc, or fails naming what is missing (`what`). */
PetscErrorCode checkpoint_open_group(const char *path, hid_t loc, const char *name,
                                     const char *what, hid_t *grp);

/* The bond/angle store as the group /topology of the open file fid. Collective. */
PetscErrorCode topology_checkpoint_write(struct sim *s, const char *path, hid_t fid);
/* Replaces the store with the file's: every rank reads it whole and keeps the entries
 * with an end it owns now (migration then takes them where their particles go). */
PetscErrorCode topology_checkpoint_read(struct sim *s, const char *path, hid_t fid);

#endif
