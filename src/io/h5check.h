/* Checked HDF5 calls: the one wrapper every HDF5 call in dmhs goes through.
 *
 *   PetscCallHDF5(path, fid = H5Fopen(path, H5F_ACC_RDONLY, fapl));
 *   PetscCallHDF5(path, H5Dwrite(...));
 *
 * A negative return (herr_t or hid_t) becomes a PETSc error that names the
 * call, the file and HDF5's own explanation (outermost and innermost entries
 * of its error stack). HDF5's automatic printing of the error stack to stderr
 * is turned off by h5check_quiet(), so the user sees one clear message. */
#ifndef DMHS_IO_H5CHECK_H
#define DMHS_IO_H5CHECK_H
#include <string.h>
#include <hdf5.h>
#include <petscsys.h>

typedef struct {
  char outer[160], inner[160];
} h5check_stack;

static inline herr_t h5check_walk_(unsigned n, const H5E_error2_t *e, void *ctx) {
  h5check_stack *st = ctx;
  /* walked downward: entry 0 is the API call, the last one the root cause */
  if (n == 0 && e->desc)
    snprintf(st->outer, sizeof(st->outer), "%s", e->desc);
  if (e->desc)
    snprintf(st->inner, sizeof(st->inner), "%s", e->desc);
  return 0;
}

/* HDF5's explanation of the last failure, "outer (cause: inner)", then clears the stack. */
static inline void h5check_describe(char *buf, size_t len) {
  h5check_stack st = {{0}, {0}};
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, h5check_walk_, &st);
  if (!st.outer[0])
    snprintf(buf, len, "no HDF5 error detail");
  else if (!strcmp(st.outer, st.inner))
    snprintf(buf, len, "%s", st.outer);
  else
    snprintf(buf, len, "%s (cause: %s)", st.outer, st.inner);
  H5Eclear2(H5E_DEFAULT);
}

/* Turns off HDF5's automatic printing of its error stack (idempotent). */
static inline PetscErrorCode h5check_quiet(void) {
  PetscFunctionBeginUser;
  PetscCheck(H5Eset_auto2(H5E_DEFAULT, NULL, NULL) >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB,
             "H5Eset_auto2 failed: cannot silence HDF5's error printing");
  PetscFunctionReturn(0);
}

#define PetscCallHDF5(file, call)                                                                  \
  do {                                                                                             \
    if ((call) < 0) {                                                                              \
      char h5check_msg_[360];                                                                      \
      h5check_describe(h5check_msg_, sizeof(h5check_msg_));                                        \
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "HDF5 call %s failed on file %s: %s",    \
              #call, (file), h5check_msg_);                                                        \
    }                                                                                              \
  } while (0)

#endif
