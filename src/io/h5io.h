/* Parallel HDF5 building blocks shared by snapshots and checkpoints (private
 * to src/io). Every rank calls every function (collective), passing the same
 * metadata; each rank writes or reads its own rows as a hyperslab at
 * offset = exclusive prefix sum of the ranks' row counts, with MPI-IO
 * collective transfers. Every HDF5 call is checked (h5check.h). */
#ifndef DMHS_IO_H5IO_H
#define DMHS_IO_H5IO_H
#include <hdf5.h>
#include <petscsys.h>
#include "dmhs/fields.h"

/* Exclusive prefix sum of n_local over comm, and the total. */
PetscErrorCode h5io_offsets(MPI_Comm comm, PetscInt n_local, PetscInt64 *offset,
                            PetscInt64 *n_global);
/* Collective create (truncating) / read-only open / close through MPI-IO. */
PetscErrorCode h5io_create(MPI_Comm comm, const char *path, hid_t *fid);
PetscErrorCode h5io_open(MPI_Comm comm, const char *path, hid_t *fid);
PetscErrorCode h5io_close(const char *path, hid_t *fid);
/* Rank 0 flushes tmp to disk and renames it to path; every rank returns the same error. */
PetscErrorCode h5io_commit(MPI_Comm comm, const char *tmp, const char *path);

/* Creates group `name` under loc (its header records no times, as no dataset's does). */
PetscErrorCode h5io_group_create(const char *path, hid_t loc, const char *name, hid_t *grp);

/* HDF5 memory type of a field's elements. */
hid_t h5io_native_type(field_kind kind);

/* Writes rows [offset, offset + n_local) of the n_global x width_file dataset `name`
 * under loc from `data` (n_local rows of f->width elements); columns beyond
 * f->width (width_file > f->width pads 2D vectors to 3D) are written as zero.
 * width_file = 1 and f->width = 1 gives a 1-D dataset. Adds the attribute "unit". */
PetscErrorCode h5io_write_rows(MPI_Comm comm, const char *path, hid_t loc, const field_desc *f,
                               const void *data, PetscInt n_local, PetscInt64 offset,
                               PetscInt64 n_global, int width_file);
/* Reads rows [offset, offset + n_local) of dataset f->name under loc into data, after
 * checking that it exists and has n_global rows of f->width components. */
PetscErrorCode h5io_read_rows(MPI_Comm comm, const char *path, hid_t loc, const field_desc *f,
                              void *data, PetscInt n_local, PetscInt64 offset, PetscInt64 n_global);

/* Attributes on an object (file, group or dataset); the same values on every rank. */
PetscErrorCode h5io_put_reals(const char *path, hid_t obj, const char *name, const double *v,
                              int n);
PetscErrorCode h5io_put_int64s(const char *path, hid_t obj, const char *name, const PetscInt64 *v,
                               int n);
PetscErrorCode h5io_put_string(const char *path, hid_t obj, const char *name, const char *value);
/* Reading them back; a missing attribute or a wrong length is an error naming the file. */
PetscErrorCode h5io_has_attr(const char *path, hid_t obj, const char *name, PetscBool *has);
PetscErrorCode h5io_get_reals(const char *path, hid_t obj, const char *name, double *v, int n);
PetscErrorCode h5io_get_int64s(const char *path, hid_t obj, const char *name, PetscInt64 *v, int n);
PetscErrorCode h5io_get_string(const char *path, hid_t obj, const char *name, char *value,
                               size_t len);

#endif
