/* The checkpoint's row datasets, each with a checksum, and its groups (checkpoint_rows.h):
 * shared by the particles' part (checkpoint.c) and the topology's (topology_checkpoint.c). */
#include <stdint.h>
#include <string.h>
#include "h5check.h"
#include "h5io.h"
#include "checkpoint_rows.h"

/* ---- checksums ----------------------------------------------------------
 * Every dataset carries the attribute "checksum": the sum, modulo 2^64, over
 * its rows of FNV-1a (64 bit) of the row's global index (8 bytes, little
 * endian) followed by the row's bytes. A sum of per-row hashes does not depend
 * on how the rows are split over the ranks, so any rank count can check it. */

static uint64_t checkpoint_row_hash(uint64_t row, const unsigned char *bytes, size_t n) {
  uint64_t h = 14695981039346656037ULL;
  for (int k = 0; k < 8; k++) {
    h ^= (row >> (8 * k)) & 0xffu;
    h *= 1099511628211ULL;
  }
  for (size_t k = 0; k < n; k++) {
    h ^= bytes[k];
    h *= 1099511628211ULL;
  }
  return h;
}

/* Checksum of rows [offset, offset + n_local) held here; reduce: add the other ranks' rows. */
static PetscErrorCode checkpoint_checksum(MPI_Comm comm, const field_desc *f, const void *data,
                                          PetscInt n_local, PetscInt64 offset, PetscBool reduce,
                                          uint64_t *sum) {
  const size_t row = fields_row_bytes(f);
  uint64_t local = 0;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < n_local; i++)
    local += checkpoint_row_hash((uint64_t)(offset + i),
                                 (const unsigned char *)data + row * (size_t)i, row);
  if (reduce)
    PetscCallMPI(MPI_Allreduce(&local, sum, 1, MPI_UINT64_T, MPI_SUM, comm));
  else
    *sum = local;
  PetscFunctionReturn(0);
}

PetscErrorCode checkpoint_write_rows(MPI_Comm comm, const char *path, hid_t loc,
                                     const field_desc *f, const void *data, PetscInt n_local,
                                     PetscInt64 offset, PetscInt64 n) {
  uint64_t sum;
  hid_t dset;
  PetscFunctionBeginUser;
  PetscCall(h5io_write_rows(comm, path, loc, f, data, n_local, offset, n, f->width));
  PetscCall(checkpoint_checksum(comm, f, data, n_local, offset, PETSC_TRUE, &sum));
  const PetscInt64 stored = (PetscInt64)sum;
  PetscCallHDF5(path, dset = H5Dopen2(loc, f->name, H5P_DEFAULT));
  PetscCall(h5io_put_int64s(path, dset, "checksum", &stored, 1));
  PetscCallHDF5(path, H5Dclose(dset));
  PetscFunctionReturn(0);
}

PetscErrorCode checkpoint_verify(MPI_Comm comm, const char *path, hid_t loc, const char *where,
                                 const field_desc *f, const void *data, PetscInt n_local,
                                 PetscInt64 offset, PetscBool reduce) {
  uint64_t sum;
  PetscInt64 stored;
  hid_t dset;
  PetscFunctionBeginUser;
  PetscCall(checkpoint_checksum(comm, f, data, n_local, offset, reduce, &sum));
  PetscCallHDF5(path, dset = H5Dopen2(loc, f->name, H5P_DEFAULT));
  PetscCall(h5io_get_int64s(path, dset, "checksum", &stored, 1));
  PetscCallHDF5(path, H5Dclose(dset));
  PetscCheck((uint64_t)stored == sum, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "checkpoint %s is corrupt: dataset /%s/%s fails its checksum (stored %016llx, read "
             "%016llx); restart "
             "from an intact copy",
             path, where, f->name, (unsigned long long)stored, (unsigned long long)sum);
  PetscFunctionReturn(0);
}

PetscErrorCode checkpoint_read_rows(MPI_Comm comm, const char *path, hid_t loc, const char *where,
                                    const field_desc *f, void *data, PetscInt n_local,
                                    PetscInt64 offset, PetscInt64 n, PetscBool reduce) {
  PetscFunctionBeginUser;
  PetscCall(h5io_read_rows(comm, path, loc, f, data, n_local, offset, n));
  PetscCall(checkpoint_verify(comm, path, loc, where, f, data, n_local, offset, reduce));
  PetscFunctionReturn(0);
}

/* Opens group `name` under loc, or fails naming what is missing. */
PetscErrorCode checkpoint_open_group(const char *path, hid_t loc, const char *name,
                                     const char *what, hid_t *grp) {
  htri_t exists;
  PetscFunctionBeginUser;
  PetscCallHDF5(path, exists = H5Lexists(loc, name, H5P_DEFAULT));
  PetscCheck(
      exists > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
      "checkpoint %s lacks the group '%s' (%s): truncated, or written by another scene or version",
      path, name, what);
  PetscCallHDF5(path, *grp = H5Gopen2(loc, name, H5P_DEFAULT));
  PetscFunctionReturn(0);
}
