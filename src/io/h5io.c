/* Parallel HDF5 building blocks shared by snapshots and checkpoints: files
 * opened through MPI-IO, per-rank row blocks written and read as hyperslabs
 * with collective transfers, attributes, and the atomic commit (flush, then
 * rename by rank 0). See h5io.h. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "h5check.h"
#include "h5io.h"

PetscErrorCode h5io_offsets(MPI_Comm comm, PetscInt n_local, PetscInt64 *offset,
                            PetscInt64 *n_global) {
  PetscInt64 n = n_local, off = 0;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Exscan(&n, &off, 1, MPIU_INT64, MPI_SUM, comm));
  if (rank == 0)
    off = 0; /* MPI_Exscan leaves rank 0's result undefined */
  PetscCallMPI(MPI_Allreduce(&n, n_global, 1, MPIU_INT64, MPI_SUM, comm));
  *offset = off;
  PetscFunctionReturn(0);
}

static PetscErrorCode h5io_fapl(MPI_Comm comm, const char *path, hid_t *fapl) {
  PetscFunctionBeginUser;
  PetscCall(h5check_quiet());
  PetscCallHDF5(path, *fapl = H5Pcreate(H5P_FILE_ACCESS));
  PetscCallHDF5(path, H5Pset_fapl_mpio(*fapl, comm, MPI_INFO_NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_create(MPI_Comm comm, const char *path, hid_t *fid) {
  hid_t fapl;
  PetscFunctionBeginUser;
  PetscCall(h5io_fapl(comm, path, &fapl));
  if ((*fid = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, fapl)) < 0) {
    char msg[360];
    h5check_describe(msg, sizeof(msg));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot create the HDF5 file %s: %s", path, msg);
  }
  PetscCallHDF5(path, H5Pclose(fapl));
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_open(MPI_Comm comm, const char *path, hid_t *fid) {
  hid_t fapl;
  PetscFunctionBeginUser;
  PetscCheck(access(path, R_OK) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot read %s: %s",
             path, strerror(errno));
  PetscCall(h5io_fapl(comm, path, &fapl));
  if ((*fid = H5Fopen(path, H5F_ACC_RDONLY, fapl)) < 0) {
    char msg[360];
    h5check_describe(msg, sizeof(msg));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN,
            "cannot open %s as an HDF5 file (truncated, or not HDF5): %s", path, msg);
  }
  PetscCallHDF5(path, H5Pclose(fapl));
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_close(const char *path, hid_t *fid) {
  PetscFunctionBeginUser;
  if (*fid >= 0)
    PetscCallHDF5(path, H5Fclose(*fid));
  *fid = -1;
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_commit(MPI_Comm comm, const char *tmp, const char *path) {
  PetscMPIInt rank;
  int err = 0, step = 0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    /* the data must be on disk before the name points to it, or a crash right
     * after the rename could leave an empty file under the good name */
    int fd = open(tmp, O_RDONLY);
    if (fd < 0)
      err = errno, step = 1;
    else {
      if (fsync(fd))
        err = errno, step = 2;
      close(fd);
    }
    if (!err && rename(tmp, path))
      err = errno, step = 3;
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&step, 1, MPI_INT, 0, comm));
  PetscCheck(!err, comm, PETSC_ERR_FILE_WRITE, "cannot %s %s%s%s: %s",
             step == 3 ? "rename" : "flush", tmp, step == 3 ? " to " : "", step == 3 ? path : "",
             strerror(err));
  PetscFunctionReturn(0);
}

hid_t h5io_native_type(field_kind kind) {
  switch (kind) {
  case FIELD_REAL:
    return H5T_NATIVE_DOUBLE;
  case FIELD_INT:
    return sizeof(PetscInt) == 8 ? H5T_NATIVE_INT64 : H5T_NATIVE_INT32;
  case FIELD_INT64:
    return H5T_NATIVE_INT64;
  }
  return -1;
}

static PetscErrorCode h5io_xfer(const char *path, hid_t *dxpl) {
  PetscFunctionBeginUser;
  PetscCallHDF5(path, *dxpl = H5Pcreate(H5P_DATASET_XFER));
  PetscCallHDF5(path, H5Pset_dxpl_mpio(*dxpl, H5FD_MPIO_COLLECTIVE));
  PetscFunctionReturn(0);
}

/* File and memory dataspaces selecting this rank's rows (none when it has none). */
static PetscErrorCode h5io_select_rows(const char *path, hid_t fspace, int rank_dims,
                                       PetscInt n_local, PetscInt64 offset, int width,
                                       hid_t *mspace) {
  PetscFunctionBeginUser;
  if (n_local == 0) {
    const hsize_t one[2] = {1, (hsize_t)width};
    PetscCallHDF5(path, H5Sselect_none(fspace));
    PetscCallHDF5(path, *mspace = H5Screate_simple(rank_dims, one, NULL));
    PetscCallHDF5(path, H5Sselect_none(*mspace));
  } else {
    const hsize_t start[2] = {(hsize_t)offset, 0}, count[2] = {(hsize_t)n_local, (hsize_t)width};
    PetscCallHDF5(path, H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, NULL, count, NULL));
    PetscCallHDF5(path, *mspace = H5Screate_simple(rank_dims, count, NULL));
  }
  PetscFunctionReturn(0);
}

/* A creation property list that records no times in the object's header: the same run
 * writes the same bytes (files compared with cmp). */
static PetscErrorCode h5io_untimed(const char *path, hid_t cls, hid_t *plist) {
  PetscFunctionBeginUser;
  PetscCallHDF5(path, *plist = H5Pcreate(cls));
  PetscCallHDF5(path, H5Pset_obj_track_times(*plist, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_group_create(const char *path, hid_t loc, const char *name, hid_t *grp) {
  hid_t gcpl;
  PetscFunctionBeginUser;
  PetscCall(h5io_untimed(path, H5P_GROUP_CREATE, &gcpl));
  PetscCallHDF5(path, *grp = H5Gcreate2(loc, name, H5P_DEFAULT, gcpl, H5P_DEFAULT));
  PetscCallHDF5(path, H5Pclose(gcpl));
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_write_rows(MPI_Comm comm, const char *path, hid_t loc, const field_desc *f,
                               const void *data, PetscInt n_local, PetscInt64 offset,
                               PetscInt64 n_global, int width_file) {
  const int rank_dims = width_file > 1 ? 2 : 1;
  const hsize_t dims[2] = {(hsize_t)n_global, (hsize_t)width_file};
  const hid_t mtype = h5io_native_type(f->kind);
  hid_t fspace, mspace, dset, dxpl, dcpl;
  void *padded = NULL;
  const void *buf = data;
  char dummy[16] = {0};
  PetscFunctionBeginUser;
  (void)comm;
  PetscCheck(width_file >= f->width, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "h5io: field %s is %d wide, file %d", f->name, f->width, width_file);
  if (width_file > f->width && n_local > 0) {
    /* pad with zero columns (2D vectors stored as 3D for ParaView) */
    const size_t elem = fields_row_bytes(f) / (size_t)f->width;
    PetscCall(PetscCalloc(elem * (size_t)width_file * (size_t)n_local, &padded));
    for (PetscInt i = 0; i < n_local; i++)
      memcpy((char *)padded + elem * (size_t)width_file * (size_t)i,
             (const char *)data + elem * (size_t)f->width * (size_t)i, elem * (size_t)f->width);
    buf = padded;
  }
  if (n_local == 0)
    buf = dummy;
  PetscCallHDF5(path, fspace = H5Screate_simple(rank_dims, dims, NULL));
  PetscCall(h5io_untimed(path, H5P_DATASET_CREATE, &dcpl));
  PetscCallHDF5(path,
                dset = H5Dcreate2(loc, f->name, mtype, fspace, H5P_DEFAULT, dcpl, H5P_DEFAULT));
  PetscCallHDF5(path, H5Pclose(dcpl));
  PetscCall(h5io_select_rows(path, fspace, rank_dims, n_local, offset, width_file, &mspace));
  PetscCall(h5io_xfer(path, &dxpl));
  /* an empty dataset has no storage to write to */
  if (n_global > 0)
    PetscCallHDF5(path, H5Dwrite(dset, mtype, mspace, fspace, dxpl, buf));
  PetscCall(h5io_put_string(path, dset, "unit", f->unit));
  PetscCallHDF5(path, H5Pclose(dxpl));
  PetscCallHDF5(path, H5Sclose(mspace));
  PetscCallHDF5(path, H5Sclose(fspace));
  PetscCallHDF5(path, H5Dclose(dset));
  PetscCall(PetscFree(padded));
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_read_rows(MPI_Comm comm, const char *path, hid_t loc, const field_desc *f,
                              void *data, PetscInt n_local, PetscInt64 offset,
                              PetscInt64 n_global) {
  const int rank_dims = f->width > 1 ? 2 : 1;
  const hid_t mtype = h5io_native_type(f->kind);
  hsize_t dims[2] = {0, 1};
  hid_t fspace, mspace, dset, dxpl, ftype;
  htri_t exists;
  char dummy[16];
  PetscFunctionBeginUser;
  (void)comm;
  PetscCallHDF5(path, exists = H5Lexists(loc, f->name, H5P_DEFAULT));
  PetscCheck(exists > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "%s lacks the dataset %s (truncated, or written by another version of dmhs)", path,
             f->name);
  PetscCallHDF5(path, dset = H5Dopen2(loc, f->name, H5P_DEFAULT));
  PetscCallHDF5(path, fspace = H5Dget_space(dset));
  const int nd = H5Sget_simple_extent_ndims(fspace);
  PetscCheck(nd == rank_dims, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "dataset %s in %s has %d dimensions, expected %d", f->name, path, nd, rank_dims);
  PetscCallHDF5(path, H5Sget_simple_extent_dims(fspace, dims, NULL));
  PetscCheck((PetscInt64)dims[0] == n_global && (rank_dims == 1 || (int)dims[1] == f->width),
             PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "dataset %s in %s is %llu x %llu but the file says %" PetscInt64_FMT
             " particles x %d components",
             f->name, path, (unsigned long long)dims[0],
             (unsigned long long)(rank_dims == 1 ? 1 : dims[1]), n_global, f->width);
  /* exact restart: reals must be stored as 8-byte floats (integers convert safely) */
  PetscCallHDF5(path, ftype = H5Dget_type(dset));
  const H5T_class_t cls = H5Tget_class(ftype);
  const size_t size = H5Tget_size(ftype);
  PetscCallHDF5(path, H5Tclose(ftype));
  PetscCheck(f->kind == FIELD_REAL ? (cls == H5T_FLOAT && size == 8) : cls == H5T_INTEGER,
             PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "dataset %s in %s has the wrong element type (class %d, %zu bytes)", f->name, path,
             (int)cls, size);
  PetscCall(h5io_select_rows(path, fspace, rank_dims, n_local, offset, f->width, &mspace));
  PetscCall(h5io_xfer(path, &dxpl));
  if (n_global > 0)
    PetscCallHDF5(path, H5Dread(dset, mtype, mspace, fspace, dxpl, n_local ? data : (void *)dummy));
  PetscCallHDF5(path, H5Pclose(dxpl));
  PetscCallHDF5(path, H5Sclose(mspace));
  PetscCallHDF5(path, H5Sclose(fspace));
  PetscCallHDF5(path, H5Dclose(dset));
  PetscFunctionReturn(0);
}

static PetscErrorCode h5io_put(const char *path, hid_t obj, const char *name, hid_t type,
                               const void *v, int n) {
  const hsize_t dims[1] = {(hsize_t)n};
  hid_t space, attr;
  PetscFunctionBeginUser;
  PetscCallHDF5(path, space = H5Screate_simple(1, dims, NULL));
  PetscCallHDF5(path, attr = H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT));
  PetscCallHDF5(path, H5Awrite(attr, type, v));
  PetscCallHDF5(path, H5Aclose(attr));
  PetscCallHDF5(path, H5Sclose(space));
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_put_reals(const char *path, hid_t obj, const char *name, const double *v,
                              int n) {
  return h5io_put(path, obj, name, H5T_NATIVE_DOUBLE, v, n);
}

PetscErrorCode h5io_put_int64s(const char *path, hid_t obj, const char *name, const PetscInt64 *v,
                               int n) {
  return h5io_put(path, obj, name, H5T_NATIVE_INT64, v, n);
}

PetscErrorCode h5io_put_string(const char *path, hid_t obj, const char *name, const char *value) {
  hid_t type, space, attr;
  const size_t len = strlen(value);
  PetscFunctionBeginUser;
  PetscCallHDF5(path, type = H5Tcopy(H5T_C_S1));
  PetscCallHDF5(path, H5Tset_size(type, len > 0 ? len : 1));
  PetscCallHDF5(path, H5Tset_strpad(type, H5T_STR_NULLPAD));
  PetscCallHDF5(path, space = H5Screate(H5S_SCALAR));
  PetscCallHDF5(path, attr = H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT));
  PetscCallHDF5(path, H5Awrite(attr, type, len > 0 ? value : ""));
  PetscCallHDF5(path, H5Aclose(attr));
  PetscCallHDF5(path, H5Sclose(space));
  PetscCallHDF5(path, H5Tclose(type));
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_has_attr(const char *path, hid_t obj, const char *name, PetscBool *has) {
  htri_t e;
  PetscFunctionBeginUser;
  PetscCallHDF5(path, e = H5Aexists(obj, name));
  *has = e > 0 ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* Opens attribute `name`, checking it exists and has n elements of the given class. */
static PetscErrorCode h5io_open_attr(const char *path, hid_t obj, const char *name, H5T_class_t cls,
                                     int n, hid_t *attr) {
  PetscBool has;
  hid_t space, type;
  hssize_t count;
  PetscFunctionBeginUser;
  PetscCall(h5io_has_attr(path, obj, name, &has));
  PetscCheck(
      has, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
      "%s lacks the attribute '%s' (not written by dmhs, truncated, or from another version)", path,
      name);
  PetscCallHDF5(path, *attr = H5Aopen(obj, name, H5P_DEFAULT));
  PetscCallHDF5(path, type = H5Aget_type(*attr));
  const H5T_class_t got = H5Tget_class(type);
  PetscCallHDF5(path, H5Tclose(type));
  PetscCallHDF5(path, space = H5Aget_space(*attr));
  PetscCallHDF5(path, count = H5Sget_simple_extent_npoints(space));
  PetscCallHDF5(path, H5Sclose(space));
  PetscCheck(got == cls && (n < 0 || count == n), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "attribute '%s' in %s has the wrong type or length (%lld values, expected %d)", name,
             path, (long long)count, n);
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_get_reals(const char *path, hid_t obj, const char *name, double *v, int n) {
  hid_t attr;
  PetscFunctionBeginUser;
  PetscCall(h5io_open_attr(path, obj, name, H5T_FLOAT, n, &attr));
  PetscCallHDF5(path, H5Aread(attr, H5T_NATIVE_DOUBLE, v));
  PetscCallHDF5(path, H5Aclose(attr));
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_get_int64s(const char *path, hid_t obj, const char *name, PetscInt64 *v,
                               int n) {
  hid_t attr;
  PetscFunctionBeginUser;
  PetscCall(h5io_open_attr(path, obj, name, H5T_INTEGER, n, &attr));
  PetscCallHDF5(path, H5Aread(attr, H5T_NATIVE_INT64, v));
  PetscCallHDF5(path, H5Aclose(attr));
  PetscFunctionReturn(0);
}

PetscErrorCode h5io_get_string(const char *path, hid_t obj, const char *name, char *value,
                               size_t len) {
  hid_t attr, ftype, mtype;
  PetscFunctionBeginUser;
  PetscCall(h5io_open_attr(path, obj, name, H5T_STRING, -1, &attr));
  PetscCallHDF5(path, ftype = H5Aget_type(attr));
  const size_t size = H5Tget_size(ftype);
  const htri_t variable = H5Tis_variable_str(ftype);
  PetscCallHDF5(path, H5Tclose(ftype));
  PetscCheck(variable == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "attribute '%s' in %s is a variable-length string: not written by dmhs", name, path);
  PetscCheck(size + 1 < len, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "attribute '%s' in %s is too long (%zu bytes)", name, path, size);
  PetscCallHDF5(path, mtype = H5Tcopy(H5T_C_S1));
  PetscCallHDF5(path, H5Tset_size(mtype, size + 1)); /* + the terminating zero */
  PetscCall(PetscMemzero(value, len));
  PetscCallHDF5(path, H5Aread(attr, mtype, value));
  PetscCallHDF5(path, H5Tclose(mtype));
  PetscCallHDF5(path, H5Aclose(attr));
  PetscFunctionReturn(0);
}
